#include "pipeline/queue.h"

#include <algorithm>
#include <future>
#include <map>

#include "pipeline/render_wait.h"

namespace toond::pipeline {
namespace {

using Poses = std::vector<const scene::SkinPose*>;

Poses poses_of(const render::RenderJob& job) {
  Poses poses;
  for (const render::JobObject& o : job.objects) poses.push_back(o.pose.get());
  return poses;
}

// Layout order, except that frames of the same poses follow the first of them.
std::vector<std::size_t> render_order(const std::vector<render::RenderJob>& frames) {
  std::vector<std::size_t> order(frames.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::map<Poses, std::size_t> first_use;
  std::vector<std::size_t> rank(frames.size());
  for (std::size_t i = 0; i < order.size(); ++i) rank[i] = first_use.emplace(poses_of(frames[i]), i).first->second;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return rank[a] < rank[b]; });
  return order;
}

}  // namespace

void queue_frames(render::RenderService& renderer, std::vector<render::RenderJob> frames,
                  std::chrono::milliseconds limit, Assembly& assembly) {
  const std::vector<std::size_t> order = render_order(frames);
  std::vector<render::RenderJob> queued;
  for (const std::size_t index : order) queued.push_back(std::move(frames[index]));
  const auto waited = wait_limit(queued.front());
  std::vector<std::future<render::RenderOutput>> futures = renderer.submit_all(std::move(queued));
  for (std::size_t i = 0; i < futures.size(); ++i) assembly.add(order[i], await_render(futures[i], waited, limit));
}

}  // namespace toond::pipeline
