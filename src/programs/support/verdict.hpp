// What a report says of an extrapolation (D16): one line, to the digits its round-off leaves.
#pragma once
#include <string>

#include "richardson.hpp"

namespace plate {

// An order to the decimals (at most 2) its noise leaves, or "-" where it is undefined.
std::string format_order(double p, double noise);

// "order 2.71, limit ... +- ..." where the order is steady; otherwise why not, and the finest value
// with its last increment.
std::string verdict(const Extrapolation& e);

}  // namespace plate
