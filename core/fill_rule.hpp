// Fill rules: which winding numbers of a set of oriented rings make up its region, for
// self-crossing and overlapping input (Clipper's four rules). An extension of the paper's
// domain, whose regions come from nesting alone (paper-notes.md, deviation "winding numbers").
// [MK89 §2.2] (regions of rings) [BRIEF §1]
// Preconditions: none.
#pragma once

#include <cstdint>
#include <string_view>

namespace mk {

// union_: OGC's reading of a multipolygon, every shell counterclockwise and every hole
// clockwise, then nonzero; the core sees it as nonzero (the orientation happens where the
// shells are known: api's fill_rule_polygon).
enum class FillRule : std::uint8_t { evenodd, nonzero, positive, negative, union_ };

// Whether a point wound w times by the rings (each taken in its given direction) is in the
// region the rule gives.
constexpr bool is_filled(FillRule rule, int w) {
  switch (rule) {
    case FillRule::evenodd: return (w & 1) != 0;
    case FillRule::nonzero:
    case FillRule::union_: return w != 0;
    case FillRule::positive: return w > 0;
    case FillRule::negative: return w < 0;
  }
  return false;
}

constexpr std::string_view fill_rule_name(FillRule rule) {
  switch (rule) {
    case FillRule::evenodd: return "evenodd";
    case FillRule::nonzero: return "nonzero";
    case FillRule::positive: return "positive";
    case FillRule::negative: return "negative";
    case FillRule::union_: return "union";
  }
  return "?";
}

}  // namespace mk
