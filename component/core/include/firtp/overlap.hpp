// Overlap time Tk at a corner between two blocks of equal feed F (Section 3).
// beta is the change of direction (0 = straight on, pi = reversal); s = sin(beta / 2).
// "Corner error" is the closest approach of the tool to the corner point.
#pragma once

#include <firtp/fir_chain.hpp>

namespace firtp {

// Eq. 13, one stage: eps = F Tk^2 s / (4 T1), 0 <= Tk <= T1.
double corner_error_eq13(double F, double beta, double Tk, double T1);
double overlap_eq13(double epsilon, double F, double beta, double T1);  // Tk, clamped to [0, T1]

// Eq. 14, two stages, both branches (Tk <= 2 T2 and 2 T2 <= Tk <= T1 + T2), clamped to [0, T1 + T2].
double overlap_eq14(double epsilon, double F, double beta, double T1, double T2);

// Any chain (this is how three and four stages are solved): the closest approach is at the middle
// of the overlap, eps = 2 F s R(Tk / 2), with R the chain's step-position response. It reduces to
// Eq. 13 and Eq. 14 for one and two stages.
double corner_error_symmetric(const FirChain& chain, double F, double beta, double Tk);
double overlap_symmetric(const FirChain& chain, double epsilon, double F, double beta);  // in [0, Td]

}  // namespace firtp
