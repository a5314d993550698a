// Text that goes into JSON must be valid UTF-8 (RFC 8259 section 8.1), but a
// shop program is often Latin-1 or Windows-1252 ("(MSG,CAFÉ)" saved by an old
// editor), and file names and command-line words are bytes. skipnc keeps every
// well-formed UTF-8 sequence as it is and replaces each ill-formed part with
// U+FFFD REPLACEMENT CHARACTER, one per maximal subpart (Unicode 15, section
// 3.9, "U+FFFD Substitution of Maximal Subparts", the practice of the WHATWG
// decoder that browsers use): the reader sees where a byte was not text.
#pragma once

#include <string>
#include <string_view>

namespace skipnc::utf8 {

// True when `s` is well-formed UTF-8 (Unicode table 3-7: no overlong forms,
// no surrogates, nothing above U+10FFFF).
bool is_valid(std::string_view s) noexcept;

// `s` with every maximal ill-formed subpart replaced by U+FFFD (EF BF BD).
// Valid text is returned unchanged.
std::string make_valid(std::string_view s);

}  // namespace skipnc::utf8
