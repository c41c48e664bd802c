#include "capsubot/io/wrap_text.hpp"

#include <sstream>

namespace capsubot {
namespace {

// A word wider than `width` in pieces of at most `width` characters, each ending after a
// comma where it can (a list of CSV columns), else cut at `width`.
std::vector<std::string> Pieces(const std::string& word, std::size_t width) {
  std::vector<std::string> pieces;
  std::size_t at = 0;
  while (word.size() - at > width) {
    const std::size_t comma = word.rfind(',', at + width - 1);
    const std::size_t cut = comma == std::string::npos || comma < at ? at + width : comma + 1;
    pieces.push_back(word.substr(at, cut - at));
    at = cut;
  }
  pieces.push_back(word.substr(at));
  return pieces;
}

}  // namespace

std::vector<std::string> WrapWords(const std::vector<std::string>& words, std::size_t width) {
  std::vector<std::string> lines;
  std::string line;
  for (const std::string& word : words) {
    if (!line.empty() && line.size() + 1 + word.size() > width) {
      lines.push_back(line);
      line.clear();
    }
    const std::vector<std::string> pieces = Pieces(word, width);
    for (std::size_t i = 0; i + 1 < pieces.size(); ++i) lines.push_back(pieces[i]);
    line += (line.empty() ? "" : " ") + pieces.back();
  }
  lines.push_back(line);
  return lines;
}

std::vector<std::string> WrapText(const std::string& text, std::size_t width) {
  std::vector<std::string> lines;
  std::istringstream paragraphs(text);
  std::string paragraph;
  while (std::getline(paragraphs, paragraph)) {
    std::istringstream in(paragraph);
    std::vector<std::string> words;
    std::string word;
    while (in >> word) words.push_back(word);
    const std::vector<std::string> wrapped = WrapWords(words, width);
    lines.insert(lines.end(), wrapped.begin(), wrapped.end());
  }
  return lines;
}

}  // namespace capsubot
