#pragma once
// A request `fapcast serve` refuses: the HTTP status, a stable rule name (kebab-case, what
// clients and tests match on) and a detail for people. The body of the answer is
// {"error": RULE, "detail": DETAIL} (spec/serve.md, "Errors").
#include <stdexcept>
#include <string>

namespace fapcast {

class RequestError : public std::runtime_error {
 public:
  RequestError(int status, std::string rule, const std::string& detail);
  int status() const { return status_; }
  const std::string& rule() const { return rule_; }
  const std::string& detail() const { return detail_; }

 private:
  int status_;
  std::string rule_;
  std::string detail_;
};

// {"error":"RULE","detail":"DETAIL"} (one line, no trailing newline).
std::string request_error_body(const RequestError& e);

}  // namespace fapcast
