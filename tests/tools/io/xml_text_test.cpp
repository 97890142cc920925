// xmlEscape: the one escaping of user text that the X3P's main.xml and the cutter SVGs share.
#include "tools/io/xml_text.h"

#include <gtest/gtest.h>

namespace scallop {
namespace {

TEST(XmlText, EscapesMarkupCharacters) {
  EXPECT_EQ(xmlEscape("a < b && c > d"), "a &lt; b &amp;&amp; c &gt; d");
  EXPECT_EQ(xmlEscape("&amp;"), "&amp;amp;");  // escaped text is escaped again, not kept
}

TEST(XmlText, DropsControlCharactersXmlForbidsButKeepsTabsNewlinesAndUtf8) {
  EXPECT_EQ(xmlEscape(std::string("x\x01y\x1f", 4) + "\tz\n"), "xy\tz\n");
  EXPECT_EQ(xmlEscape("\xc2\xb5m"), "\xc2\xb5m");  // UTF-8 bytes are >= 0x80: kept
}

}  // namespace
}  // namespace scallop
