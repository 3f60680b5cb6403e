#pragma once
// A Gaussian disturbance on one grid axis: the probability of each interval of the axis under
// Normal(mean, deviation²), and the two constants the error bound needs (docs/geometry.md,
// "Gaussian disturbances").
//
// The normal CDF is irrational, so these probabilities cannot be exact. They are computed in
// doubles with std::erfc, rounded to a fixed binary grid and carried as exact rationals (the
// bisimulation engine compares rows exactly), and everything that makes them inexact has an a
// priori bound, gaussian_row_tolerance(), which the partition adds to the context's epsilon:
//
// - truncation: only the intervals that meet (mean - k·deviation, mean + k·deviation), k =
//   7.2, get an entry; the mass beyond, P(|Z| >= 7.2) < 6.2e-13 (Mills ratio: 2·φ(7.2)/7.2),
//   is counted as leaving the domain, which is where it goes when it lies outside the domain
//   and a misplacement when it lies inside;
// - every tail evaluation 0.5·erfc(z/√2) is taken to be within kTailError = 1e-14 of the true
//   tail (glibc documents erfc to a few ulps, about 1e-15 absolutely; the argument's rounding
//   adds less than 2e-16);
// - the subtraction of two tails rounds once or twice (at most 2^-52 in all), and the result
//   is rounded to a multiple of 2^-48;
// - when rounding makes the entries sum past 1, the excess is taken from the largest, which
//   at most doubles the entries' total error.

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "support/rational.hpp"

namespace oasis::geom {

// The row covers the intervals that meet mean ± k · deviation, k = 7.2: the tail beyond holds
// less than 1e-12 of the mass, and a row costs the cells under 14.4 deviations per axis.
Rational truncation_deviations();

// A rational strictly below √(2π) = 2.5066282746...: 2.506628. Dividing by it, as the error
// bound does, rounds the bound up.
Rational sqrt_two_pi_below();

// (interval index, probability) for the intervals of the axis cut at `breaks` (strictly
// increasing, the domain's ends first and last) that meet the truncated support of
// Normal(mean, deviation²); probabilities positive, their sum at most 1. The rest of the mass
// is the chance of leaving the domain on this axis.
std::vector<std::pair<std::uint32_t, Rational>> gaussian_interval_probabilities(
    const Rational& mean, const Rational& deviation, const std::vector<Rational>& breaks);

// An upper bound, in total variation, on the distance between what
// gaussian_interval_probabilities returns (the rest of the mass counted as leaving the axis)
// and the exact distribution of a Gaussian successor over the `intervals` intervals of the
// axis and the outside, whatever the mean and deviation.
Rational gaussian_row_tolerance(std::size_t intervals);

}  // namespace oasis::geom
