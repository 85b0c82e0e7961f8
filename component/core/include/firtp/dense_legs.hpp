// A dense junction's step against its two legs, in closed form.
//
// In a run of short blocks each block has one speed (lookahead.hpp, dense). At the junction after
// block i the velocity steps from b u to a u'; the step's box
//     T1(b, a) = max_k |a u'_k - b u_k| / C_k
// must fit within each leg: T1 <= L / b (block i) and T1 <= L' / a (block i + 1). Braking towards
// the end of the known path, a = min(b, n) with n the next block's entry bound, and the highest b
// that passes is block i's exit bound: on pcb2gcode output that bound is searched for some 27
// junctions at every add. Per axis the two conditions are a quadratic and a linear inequality in
// b, so where they flip has a closed form. The look-ahead uses it as its search's first guess
// (search::highest_near): the test still decides, the closed form only saves tests.
#pragma once

#include <firtp/types.hpp>

#include <optional>

namespace firtp {

struct DenseLegs {
    const AxisVector& u;       // block i's direction
    const AxisVector& u_next;  // block i + 1's
    const AxisVector& cap;     // C_k (infinite: the axis does not bound the box)
    int axes = 0;
    double length = 0.0, next_length = 0.0;  // L, L'
};

// Where "T1(b, min(b, n)) fits both legs" flips from passing to failing, for b >= 0. None where
// the passing speeds need not be one interval from 0 (there a guess could mislead the search).
std::optional<double> dense_leg_flip(const DenseLegs& legs, double n);

}  // namespace firtp
