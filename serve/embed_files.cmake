# Writes OUT: a C++ source defining embedded_page_html() and embedded_page_script() from
# web/index.html and web/avatar.js (cmake -P, run at build time when they change).
function(embed var file)
  file(READ ${file} hex HEX)
  string(LENGTH "${hex}" n)
  math(EXPR bytes "${n} / 2")
  string(REGEX REPLACE "([0-9a-f][0-9a-f])" "0x\\1," hex "${hex}")
  string(REGEX REPLACE "(0x..,0x..,0x..,0x..,0x..,0x..,0x..,0x..,0x..,0x..,0x..,0x..,0x..,0x..,0x..,0x..,)" "\\1\n" hex "${hex}")
  set(${var} "constexpr unsigned char k${var}[] = {\n${hex}0};\nconstexpr std::size_t k${var}Bytes = ${bytes};\n" PARENT_SCOPE)
endfunction()
embed(Html ${WEB}/index.html)
embed(Script ${WEB}/avatar.js)
file(WRITE ${OUT}.tmp "// Generated from serve/web by serve/embed_files.cmake: do not edit.
#include <cstddef>
#include <string_view>
namespace fapcast {
namespace {
${Html}${Script}}  // namespace
std::string_view embedded_page_html() { return {reinterpret_cast<const char*>(kHtml), kHtmlBytes}; }
std::string_view embedded_page_script() { return {reinterpret_cast<const char*>(kScript), kScriptBytes}; }
}  // namespace fapcast
")
file(RENAME ${OUT}.tmp ${OUT})
