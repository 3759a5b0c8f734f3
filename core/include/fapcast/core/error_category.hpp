#pragma once
// A std::error_category with a name and a function from code to message: the categories of the
// hot paths that report with std::error_code (FBA decoding, RTP), each made once by the
// function that returns it.
#include <string>
#include <system_error>

namespace fapcast {

class NamedErrorCategory final : public std::error_category {
 public:
  using Message = std::string (*)(int code);
  NamedErrorCategory(const char* name, Message message) : name_(name), message_(message) {}
  const char* name() const noexcept override { return name_; }
  std::string message(int code) const override { return message_(code); }

 private:
  const char* name_;
  Message message_;
};

}  // namespace fapcast
