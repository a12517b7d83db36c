#pragma once
// Argument lists as text: splitting a plan value into words, and quoting words for a POSIX shell.
#include <string>
#include <vector>

namespace vlo::batch
{
/// Splits at blanks; "double quotes" group a word that contains blanks (the quotes are dropped).
/// Throws InputError(where, ...) for an unterminated quote.
std::vector<std::string> splitWords(const std::string& text, const std::string& where);

/// The word as one POSIX shell word: unchanged when it holds only safe characters, otherwise in
/// single quotes (a ' inside becomes '\'').
std::string shellQuote(const std::string& word);
/// shellQuote of each word, joined by spaces.
std::string shellJoin(const std::vector<std::string>& words);

/// A number as the shortest text that reads back the same ("2.5", "0.1", "50"): a plan value or an argument.
std::string numberWord(double v);

/// The inverse of splitWords for writing a plan value: words with blanks get double quotes.
std::string joinWords(const std::vector<std::string>& words);
}  // namespace vlo::batch
