#pragma once
// The result of a convergence case: a quantity measured at several spacings against its
// expectation. Checks (tolerances stated where each case calls this):
// - the error at the finest spacing within the physics case's tolerance;
// - the observed order p (slope of log |error| against log dx) is positive: the error shrinks as
//   the particles get finer. SPH at a fixed ratio h / dx is not guaranteed to converge (its
//   kernel-sum errors do not vanish with dx, Quinlan et al. 2006), so p > 0 is the claim
//   checked, and p itself is reported.
// The errors at every spacing are in the series and the case's details.
#include "framework/validation_case.hpp"

#include <string>
#include <vector>

namespace mssph::validation {

// The check that an error shrinks as the particles get finer: the observed order of `error`
// against `spacing` (observed_order, fits.hpp) at least smallest_order.
Check observed_order_check(std::string quantity, const std::vector<double>& spacing, const std::vector<double>& error,
                           double smallest_order);

CaseResult convergence_result(const std::string& quantity, const std::vector<double>& spacing,
                              const std::vector<double>& expected, const std::vector<double>& measured,
                              double finest_tolerance, const std::string& backend);

// The result of a convergence case whose scheme converges to a limit that differs from the
// expectation by more than its discretisation error at the spacings measured (a model error that
// the case's README states and measures). The order of the error against the expectation then
// says nothing; the sequence's own convergence does (Roache, Verification and Validation in
// Computational Science and Engineering, 1998, ch. 5). Checks:
// - the value at the finest spacing within finest_tolerance of the expectation;
// - the last change of measured / expected between successive spacings no larger than the
//   first: the values settle as the particles get finer (the ratio, since the expectation may
//   move with the spacing).
// The details give the signed errors, the changes, and over the three finest spacings the
// apparent order and the Richardson-extrapolated limit (grid_convergence, fits.hpp). Needs three
// spacings or more.
CaseResult self_convergence_result(const std::string& quantity, const std::vector<double>& spacing,
                                   const std::vector<double>& expected, const std::vector<double>& measured,
                                   double finest_tolerance, const std::string& backend);

}  // namespace mssph::validation
