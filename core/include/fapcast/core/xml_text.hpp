#pragma once
// Text placed in XML (and SVG): the five characters XML reserves, written as entities.
#include <string>
#include <string_view>

namespace fapcast {

// `text` with & < > " ' as &amp; &lt; &gt; &quot; &apos;: safe inside an element and inside a
// quoted attribute. Other bytes pass unchanged (the caller's text is UTF-8).
std::string escape_xml(std::string_view text);

}  // namespace fapcast
