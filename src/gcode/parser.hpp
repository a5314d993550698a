// Lexer and parser: text of one block -> gcode::Block. Syntax only.
#pragma once

#include <string_view>

#include "core/diag.hpp"
#include "gcode/ast.hpp"

namespace skipnc::gcode {

struct ParseLimits {
  int max_bracket_depth = 64;  // nesting of [ ] (the dialect may refuse deeper)
  int max_digits = 15;         // significant digits in one number
  Syntax syntax = Syntax::kMacroB;
  // `//` outside a ( ) comment starts a comment to the end of the block
  // (CompassNC, seed 003's example: `N12 G31 X100 F200 // ...`).
  bool slash_comments = false;
  // `[expr] M99 ...`: a bracketed expression at the head of a block that
  // holds M99 is its condition (Haas's conditional M99; Block::condition).
  bool conditional_m99 = false;
};

// Parses the text of exactly one block (no end-of-block character inside,
// except within comments). `loc` is the location of text[0]. On success `out`
// holds the block; on failure `out` is unspecified and the error says where.
[[nodiscard]] Result<void> parse_block(std::string_view text, SourceLoc loc, std::uint64_t offset,
                                       Block& out, const ParseLimits& limits = {});

}  // namespace skipnc::gcode
