#pragma once
// An answer's body too large to hold whole as one string (a large line
// drawing): written as it goes out, a piece at a time, to a receiver that
// says false once its client has gone. Such an answer carries no ETag (its
// bytes are not hashed before they leave) and is not kept in the result
// cache.
#include <functional>
#include <string_view>

namespace toond::pipeline {

using BodySend = std::function<bool(std::string_view)>;

struct StreamedBody {
  std::function<void(const BodySend&)> write;
};

}  // namespace toond::pipeline
