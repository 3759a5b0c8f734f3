#include "fapcast/core/xml_text.hpp"

#include <gtest/gtest.h>

namespace fapcast {
namespace {

TEST(EscapeXml, WritesTheFiveReservedCharactersAsEntities) {
  EXPECT_EQ(escape_xml(R"(a<b & "c" 'd'>)"), "a&lt;b &amp; &quot;c&quot; &apos;d&apos;&gt;");
}

TEST(EscapeXml, LeavesOtherTextAlone) {
  EXPECT_EQ(escape_xml("/home/ana/Mädchen.wav"), "/home/ana/Mädchen.wav");
  EXPECT_EQ(escape_xml(""), "");
  EXPECT_EQ(escape_xml("&amp;"), "&amp;amp;");  // already-escaped text is escaped again: the caller's text is plain
}

}  // namespace
}  // namespace fapcast
