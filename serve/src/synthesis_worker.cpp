#include "synthesis_worker.hpp"

namespace fapcast {

SynthesisWorker::SynthesisWorker(std::size_t threads) {
  for (std::size_t i = 0; i < (threads == 0 ? 1 : threads); ++i) threads_.emplace_back([this] { run(); });
}

SynthesisWorker::~SynthesisWorker() { stop(); }

void SynthesisWorker::submit(bool urgent, std::function<void()> job) {
  {
    std::lock_guard lock(mutex_);
    if (stopping_) return;
    (urgent ? urgent_ : later_).push_back(std::move(job));
  }
  wake_.notify_one();
}

void SynthesisWorker::stop() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
    urgent_.clear();
    later_.clear();
  }
  wake_.notify_all();
  for (auto& t : threads_)
    if (t.joinable()) t.join();
  threads_.clear();
}

std::size_t SynthesisWorker::waiting() const {
  std::lock_guard lock(mutex_);
  return urgent_.size() + later_.size();
}

void SynthesisWorker::run() {
  for (;;) {
    std::function<void()> job;
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [this] { return stopping_ || !urgent_.empty() || !later_.empty(); });
      if (stopping_) return;
      auto& from = urgent_.empty() ? later_ : urgent_;
      job = std::move(from.front());
      from.pop_front();
    }
    job();
  }
}

}  // namespace fapcast
