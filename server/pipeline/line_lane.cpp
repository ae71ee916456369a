#include "pipeline/line_lane.h"

#include "render/run/render_service.h"
#include "request_error.h"

namespace toond::pipeline {

LineLane::Turn::~Turn() { lane_->release(); }

std::unique_ptr<LineLane::Turn> LineLane::wait_turn(const std::string& client, Clock::time_point deadline,
                                                    std::chrono::milliseconds limit) {
  std::unique_lock lock(mutex_);
  if (waiting_ >= capacity_) throw render::QueueFull();
  auto ticket = std::make_shared<Ticket>();
  queue_.push(client, ticket);
  ++waiting_;
  grant();
  if (!granted_.wait_until(lock, deadline, [&] { return ticket->granted; })) {
    ticket->abandoned = true;  // dropped when its turn comes
    --waiting_;
    throw RequestError(
        503, "deadline_exceeded",
        "the line drawing did not start within the limit --render-timeout = " + std::to_string(limit.count()) + " ms");
  }
  --waiting_;
  return std::make_unique<Turn>(this);
}

std::size_t LineLane::waiting() const {
  std::lock_guard lock(mutex_);
  return waiting_;
}

void LineLane::release() {
  std::lock_guard lock(mutex_);
  --active_;
  grant();
}

void LineLane::grant() {
  bool any = false;
  while (active_ < running_ && !queue_.empty()) {
    std::shared_ptr<Ticket> next = queue_.pop();
    if (next->abandoned) continue;
    next->granted = true;
    ++active_;
    any = true;
  }
  if (any) granted_.notify_all();
}

}  // namespace toond::pipeline
