#pragma once
// The one place the serve library includes Boost.Beast (HTTP/1.1 and WebSocket, Boost 1.74),
// after fapcast's Asio settings (fapcast/transport/asio.hpp).
#include "fapcast/transport/asio.hpp"

#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/post.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>

namespace fapcast {
namespace beast = boost::beast;
namespace http = boost::beast::http;
namespace websocket = boost::beast::websocket;
using tcp = boost::asio::ip::tcp;
}  // namespace fapcast
