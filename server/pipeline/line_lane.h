#pragma once
// Where vector line drawings (output svg) wait their turn. A drawing needs
// no GL, so it does not take a render thread from the renders that do (on
// a GPU host that thread would leave the GPU idle while it worked): it runs
// on its request's own thread, which waits for it anyway, its runs spread
// over the cores (render/vector/line_drawing.h). Each drawing already uses
// every core, so only a few run at once; the rest wait here as renders wait
// in the render queue: bounded (a full lane answers 503 busy at once),
// clients taking turns (render/run/fair_queue.h), and given up at their
// deadline (503 deadline_exceeded).
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <memory>
#include <mutex>
#include <string>

#include "render/run/fair_queue.h"

namespace toond::pipeline {

class LineLane {
 public:
  using Clock = std::chrono::steady_clock;
  // At most `running` drawings at once, `capacity` more waiting.
  LineLane(std::size_t running, std::size_t capacity) : running_(running), capacity_(capacity) {}
  LineLane() : LineLane(2, 32) {}

  // A turn in the lane, held until it goes out of scope.
  class Turn {
   public:
    explicit Turn(LineLane* lane) : lane_(lane) {}
    ~Turn();
    Turn(const Turn&) = delete;
    Turn& operator=(const Turn&) = delete;

   private:
    LineLane* lane_;
  };

  // Waits for `client`'s turn. Throws render::QueueFull when `capacity`
  // drawings wait already, RequestError 503 deadline_exceeded when
  // `deadline` passes first (`limit`: --render-timeout, for the message).
  std::unique_ptr<Turn> wait_turn(const std::string& client, Clock::time_point deadline,
                                  std::chrono::milliseconds limit);

  std::size_t waiting() const;

 private:
  struct Ticket {
    bool granted = false;
    bool abandoned = false;
  };
  void release();
  // Under mutex_: hands free places to the next tickets in turn.
  void grant();

  const std::size_t running_;
  const std::size_t capacity_;
  mutable std::mutex mutex_;
  std::condition_variable granted_;
  std::size_t active_ = 0;
  std::size_t waiting_ = 0;
  render::FairQueue<std::shared_ptr<Ticket>> queue_;
};

}  // namespace toond::pipeline
