#pragma once
// The one place fapcast includes Boost.Asio. Boost 1.74's <boost/asio/...> headers, compiled as
// C++20 by GCC 12, detect coroutine support and then use std::exchange before <utility> is
// included; including <utility> first (and not using Asio's co_await support) avoids it.
#include <utility>

#ifndef BOOST_ASIO_DISABLE_CO_AWAIT
#define BOOST_ASIO_DISABLE_CO_AWAIT 1
#endif
#ifndef BOOST_ASIO_NO_DEPRECATED
#define BOOST_ASIO_NO_DEPRECATED 1
#endif

#include <boost/asio/buffer.hpp>
#include <boost/asio/ip/host_name.hpp>
#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/multicast.hpp>
#include <boost/asio/ip/udp.hpp>
#include <boost/asio/ip/unicast.hpp>
#include <boost/asio/signal_set.hpp>
#include <boost/asio/steady_timer.hpp>

namespace fapcast {
namespace asio = boost::asio;
using udp = boost::asio::ip::udp;
}  // namespace fapcast
