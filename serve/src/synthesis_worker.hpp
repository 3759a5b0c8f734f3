#pragma once
// The threads that synthesise sentences off the network thread: jobs run in order of urgency
// (a session's first sentence, which a client is waiting for, before the sentences that follow),
// then of arrival. The queue is bounded by the sessions it serves (each has at most one job).
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace fapcast {

class SynthesisWorker {
 public:
  explicit SynthesisWorker(std::size_t threads);
  ~SynthesisWorker();
  SynthesisWorker(const SynthesisWorker&) = delete;
  SynthesisWorker& operator=(const SynthesisWorker&) = delete;

  // Runs `job` on a worker thread. Jobs submitted after stop() are dropped.
  void submit(bool urgent, std::function<void()> job);
  // Lets running jobs finish, drops waiting ones, joins the threads.
  void stop();
  std::size_t waiting() const;

 private:
  void run();
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<std::function<void()>> urgent_, later_;
  bool stopping_ = false;
  std::vector<std::thread> threads_;
};

}  // namespace fapcast
