// What a report says of an extrapolation (D13): one line, to the digits its round-off leaves.
#pragma once
#include <string>

#include "richardson.hpp"

namespace plate {

// A target's status in a report's target lines, bold either way so that a reader scanning finds it.
inline std::string target_status(bool met) { return met ? "**met**" : "**not met**"; }

// An order to the decimals (at most 2) its noise leaves, or "-" where it is undefined.
std::string format_order(double p, double noise);

// "order 2.71, limit ... +- ..." where the order is steady; otherwise why not, and the finest value
// with its last increment. The second form prints the bar as the caller gives it, so that a report
// can state one bar for a limit wherever it names it.
std::string verdict(const Extrapolation& e);
std::string verdict(const Extrapolation& e, const std::string& bar);

// The bar as a bare number: where it is within the noise, the noise's bound.
std::string bar_number(const Extrapolation& e, int digits = 3);
// Whether the bar printed is the noise's bound rather than the bar itself.
bool bar_is_roundoff(const Extrapolation& e);

}  // namespace plate
