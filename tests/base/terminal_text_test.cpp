// Text from users' files printed to a terminal: control characters shown,
// not obeyed (base/terminal_text.h).

#include <gtest/gtest.h>

#include "base/terminal_text.h"

namespace hsb {
namespace {

TEST(TerminalText, ControlCharactersAreShownNotObeyed) {
  // An escape sequence that would clear the screen, a bell, a carriage
  // return that would overwrite the line, DEL.
  EXPECT_EQ(shown("block \x1b[2J\x1b]0;title\x07 end\r\x7f"), "block \\x1b[2J\\x1b]0;title\\x07 end\\x0d\\x7f");
  // C1's CSI as UTF-8, and bytes that are not UTF-8.
  EXPECT_EQ(shown("a\xc2\x9b" "31mb \xff\xc3"), "a\\u009b31mb \\xff\\xc3");
  // Line feeds, tabs and real UTF-8 stay.
  EXPECT_EQ(shown("λ₃ (Pa)\tσ\nnext é 中"), "λ₃ (Pa)\tσ\nnext é 中");
}

}  // namespace
}  // namespace hsb
