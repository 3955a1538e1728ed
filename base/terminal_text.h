#pragma once
// Text from a user's files (a key, a header's field, a block's or a file's
// name) printed to a terminal: its control characters shown, not obeyed.
// An escape sequence in a file's header could otherwise clear the screen,
// retitle the window or hide the message it sits in.

#include <string>

namespace hsb {

// `text` with every control character but line feed and tab (C0, DEL, and
// C1 as UTF-8), and every byte that is not UTF-8, written as \xNN (\u00NN
// for C1); everything else, UTF-8 included, as it is.
std::string shown(const std::string& text);

}  // namespace hsb
