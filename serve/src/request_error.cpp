#include "fapcast/serve/request_error.hpp"

#include <nlohmann/json.hpp>

namespace fapcast {

RequestError::RequestError(int status, std::string rule, const std::string& detail)
    : std::runtime_error(rule + ": " + detail), status_(status), rule_(std::move(rule)), detail_(detail) {}

std::string request_error_body(const RequestError& e) {
  return nlohmann::json{{"error", e.rule()}, {"detail", e.detail()}}.dump(-1, ' ', false,
                                                                          nlohmann::json::error_handler_t::replace);
}

}  // namespace fapcast
