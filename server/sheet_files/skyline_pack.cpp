#include "sheet_files/skyline_pack.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <set>
#include <tuple>

namespace toond::sheet_files {
namespace {

// A stretch of the skyline: from x, w wide, everything below y taken.
struct Segment {
  int x = 0;
  int y = 0;
  int w = 0;
};

class Skyline {
 public:
  explicit Skyline(int width) : width_(width), segments_{{0, 0, width}} {}

  // The lowest (then leftmost) top-left corner where something `w` wide
  // rests on the skyline; x < 0 when it is wider than the skyline.
  PackPlace lowest(int w) const {
    PackPlace best{-1, 0};
    for (std::size_t i = 0; i < segments_.size(); ++i) {
      const int x = segments_[i].x;
      if (x + w > width_) break;
      int y = 0;
      for (std::size_t j = i; j < segments_.size() && segments_[j].x < x + w; ++j) y = std::max(y, segments_[j].y);
      if (best.x < 0 || y < best.y) best = {x, y};
    }
    return best;
  }

  // Everything under [x, x + w) up to `top` is taken.
  void raise(int x, int w, int top) {
    std::vector<Segment> next;
    const int end = x + w;
    bool added = false;
    const auto add = [&] {
      if (!added) next.push_back({x, top, w});
      added = true;
    };
    for (const Segment& s : segments_) {
      const int s_end = s.x + s.w;
      if (s_end <= x) {
        next.push_back(s);
        continue;
      }
      if (s.x < x) next.push_back({s.x, s.y, x - s.x});
      if (s.x >= end) {
        add();
        next.push_back(s);
        continue;
      }
      add();
      if (s_end > end) next.push_back({end, s.y, s_end - end});
    }
    add();
    segments_.clear();
    for (const Segment& s : next) {
      if (!segments_.empty() && segments_.back().y == s.y) {
        segments_.back().w += s.w;
      } else {
        segments_.push_back(s);
      }
    }
  }

 private:
  int width_;
  std::vector<Segment> segments_;
};

int power_of_two_at_least(int n) {
  int p = 1;
  while (p < n) p *= 2;
  return p;
}

// Tallest first, then widest: rows of like heights leave the least gap.
std::vector<std::size_t> placing_order(const std::vector<PackSize>& sizes) {
  std::vector<std::size_t> order(sizes.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return std::tie(sizes[b].h, sizes[b].w) < std::tie(sizes[a].h, sizes[a].w);
  });
  return order;
}

// Every rectangle within `width`; its padding may run past the right and
// bottom edges, where it has no neighbour.
Packing pack_at_width(const std::vector<PackSize>& sizes, const std::vector<std::size_t>& order, int width,
                      int padding) {
  Skyline skyline(width + padding);
  Packing packing;
  packing.places.resize(sizes.size());
  for (std::size_t i : order) {
    const PackSize& size = sizes[i];
    const PackPlace place = skyline.lowest(size.w + padding);
    skyline.raise(place.x, size.w + padding, place.y + size.h + padding);
    packing.places[i] = place;
    packing.width = std::max(packing.width, place.x + size.w);
    packing.height = std::max(packing.height, place.y + size.h);
  }
  return packing;
}

// Sheet widths worth trying: around the square root of the area, and as
// wide as the first few rectangles side by side (rows of like tiles).
std::set<int> candidate_widths(const std::vector<PackSize>& sizes, const std::vector<std::size_t>& order,
                               const PackOptions& options) {
  int widest = 0;
  long long row = 0;
  double area = 0;
  for (const PackSize& s : sizes) {
    widest = std::max(widest, s.w);
    row += s.w + options.padding;
    area += static_cast<double>(s.w + options.padding) * (s.h + options.padding);
  }
  const int narrowest = widest;
  const int widest_sheet = static_cast<int>(std::min<long long>(row, 1 << 24));
  std::set<int> widths;
  const auto consider = [&](long long w) {
    if (w < narrowest || w > widest_sheet) return;
    widths.insert(options.power_of_two ? power_of_two_at_least(static_cast<int>(w)) : static_cast<int>(w));
  };
  consider(narrowest);
  consider(widest_sheet);
  const double side = std::sqrt(area);
  for (int k = 0; k <= 24; ++k) consider(std::lround(side * std::pow(2.0, (k - 8) / 8.0)));
  long long side_by_side = 0;
  for (std::size_t n = 0; n < order.size() && n < 64; ++n) {
    side_by_side += sizes[order[n]].w + (n ? options.padding : 0);
    consider(side_by_side);
  }
  return widths;
}

}  // namespace

Packing pack_rects(const std::vector<PackSize>& sizes, const PackOptions& options) {
  if (sizes.empty()) return {};
  const std::vector<std::size_t> order = placing_order(sizes);
  Packing best;
  std::tuple<bool, long long, int, int> best_cost{false, 0, 0, 0};
  for (int width : candidate_widths(sizes, order, options)) {
    Packing packing = pack_at_width(sizes, order, width, options.padding);
    if (options.power_of_two) {
      packing.width = power_of_two_at_least(packing.width);
      packing.height = power_of_two_at_least(packing.height);
    }
    // A sheet no more than twice as long as it is wide, where one fits (a
    // strip has the least area once padding counts, but outgrows the
    // textures a GPU takes); then the least area, the squarer, the narrower.
    const int longer = std::max(packing.width, packing.height);
    const int shorter = std::min(packing.width, packing.height);
    const std::tuple<bool, long long, int, int> cost{
        longer > 2 * shorter, static_cast<long long>(packing.width) * packing.height, longer, packing.width};
    if (best.places.empty() || cost < best_cost) {
      best = std::move(packing);
      best_cost = cost;
    }
  }
  return best;
}

}  // namespace toond::sheet_files
