#pragma once
// Pacing against steady_clock: wait on a timer until an instant, or report how late it already is.
#include <chrono>

#include "fapcast/transport/asio.hpp"

namespace fapcast::detail {

// Waits on `timer` until `deadline` and returns zero, or, when `deadline` has passed, returns how
// long ago without waiting.
inline std::chrono::steady_clock::duration wait_until(asio::steady_timer& timer,
                                                      std::chrono::steady_clock::time_point deadline) {
  const auto now = std::chrono::steady_clock::now();
  if (now >= deadline) return now - deadline;
  timer.expires_at(deadline);
  boost::system::error_code wait_error;
  timer.wait(wait_error);
  return std::chrono::steady_clock::duration::zero();
}

}  // namespace fapcast::detail
