#pragma once
// The render queue's order: clients take turns. Each client's requests wait
// in their own line, first come first served, and the lines are served
// round-robin, so one client's burst of a hundred requests puts another's
// single request behind at most one of them, not behind all a hundred. No
// line starves: every client with work waiting is served once per round.
#include <cstddef>
#include <deque>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace toond::render {

template <class Item>
class FairQueue {
 public:
  void push(const std::string& client, Item item) {
    std::deque<Item>& line = lines_[client];
    if (line.empty()) turns_.push_back(client);
    line.push_back(std::move(item));
    ++size_;
  }

  bool empty() const { return size_ == 0; }
  std::size_t size() const { return size_; }

  // The first item of the client whose turn it is; that client's turn then
  // goes to the back of the round. Not on an empty queue.
  Item pop() {
    const std::string client = std::move(turns_.front());
    turns_.pop_front();
    auto line = lines_.find(client);
    Item item = std::move(line->second.front());
    line->second.pop_front();
    if (line->second.empty()) {
      lines_.erase(line);
    } else {
      turns_.push_back(client);
    }
    --size_;
    return item;
  }

  // Everything queued, emptying the queue (in no particular order).
  std::vector<Item> take_all() {
    std::vector<Item> all;
    for (auto& [client, line] : lines_) {
      for (Item& item : line) all.push_back(std::move(item));
    }
    lines_.clear();
    turns_.clear();
    size_ = 0;
    return all;
  }

 private:
  std::unordered_map<std::string, std::deque<Item>> lines_;
  std::deque<std::string> turns_;  // clients with work waiting, next first
  std::size_t size_ = 0;
};

}  // namespace toond::render
