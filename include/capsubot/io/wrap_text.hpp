#pragma once
// Text broken into lines of a given width at spaces: the helps of the command line and the
// docstrings of the Python module.

#include <cstddef>
#include <string>
#include <vector>

namespace capsubot {

/// `words` into lines of at most `width` characters, one space between words; a word wider
/// than `width` is broken into pieces of at most `width`, each ending after a comma where it
/// can (a list of CSV columns).
std::vector<std::string> WrapWords(const std::vector<std::string>& words, std::size_t width);

/// `text` broken at spaces into lines of at most `width` characters (WrapWords); its own line
/// breaks are kept.
std::vector<std::string> WrapText(const std::string& text, std::size_t width);

}  // namespace capsubot
