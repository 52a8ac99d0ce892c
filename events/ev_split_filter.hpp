#pragma once
// Interval layers of two exact tests of the EV end-object split (events/ev_interval_split.cpp): which
// candidate segments in the wedge plane and which of their endpoints can matter for the free interval
// [t0, t1] (docs/theory.md section 9, "Scale"). Points of the wedge plane are given by their scaled affine
// coordinates (alpha, beta) (X = V + (alpha a + beta b) / |n|^2); sigma = alpha + beta, and the line of the
// pencil through X has parameter t = beta / sigma. The answers come from interval enclosures only and are
// certificates: an undecided case is left to the exact test, so rounding never decides.
#include <CGAL/Interval_nt.h>

#include <array>
#include <utility>

namespace exactvis {

enum class FilterAnswer { No, Yes, Unknown };

// The exact test keeps a segment (p, q) unless sigma has one nonzero sign at both ends and both ends' t lie
// below t0, or both above t1. Input: enclosures of alpha_p, beta_p, alpha_q, beta_q, and of t0 and t1
// ([lo, hi] pairs). Output: No when the exact test certainly drops the segment, Yes when it certainly keeps
// it (sigma's signs certainly differ, or the t range certainly overlaps [t0, t1]), Unknown otherwise.
FilterAnswer segment_t_range_meets(const std::array<CGAL::Interval_nt<>, 4>& ends,
                                   const std::pair<double, double>& t0, const std::pair<double, double>& t1);

// The exact test keeps an endpoint iff (sigma >= |n|^2 or sigma < 0) and t0 < t < t1. Input: enclosures of
// its alpha and beta, a lower bound nn_lo of |n|^2, enclosures of t0 and t1. Output: true only when the exact
// test certainly drops it (0 <= sigma < nn_lo, or sigma certainly nonzero and t certainly <= t0 or >= t1).
bool endpoint_certainly_dropped(const CGAL::Interval_nt<>& alpha, const CGAL::Interval_nt<>& beta, double nn_lo,
                                const std::pair<double, double>& t0, const std::pair<double, double>& t1);

}  // namespace exactvis
