#include "acst_mpm/graded_axis.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "acst_common/double_pair.hpp"

namespace acst::mpm {
namespace {

using common::DoublePair;

// The three quadratic B-splines N_{k-2}, N_{k-1}, N_k that are not zero on knot interval k, at x
// (de Boor's triangle: degree 1 from the interval's ends, degree 2 from its neighbours'). The
// weights are bound by the divider: its six divisions go two at a time (the same quotients).
void splines_on_interval(const double* t, int k, double x, double out[3]) {
  const double a = t[k], b = t[k + 1];
  const double up = t[k + 2], down = t[k - 1];
  const DoublePair degree1 = DoublePair{b - x, x - a} / DoublePair{b - a, b - a};  // N_{k-1,1}, N_{k,1}
  const DoublePair left = DoublePair{b - x, x - down} / DoublePair{b - down, b - down};
  const DoublePair right = DoublePair{up - x, x - a} / DoublePair{up - a, up - a};
  out[0] = left[0] * degree1[0];
  out[1] = left[1] * degree1[0] + right[0] * degree1[1];
  out[2] = right[1] * degree1[1];
}

// The intervals between a window's edge and an end node D further out, outward: cells growing
// by the grading's ratio up to about its largest, then at least 4 even cells b whose last has
// the end node at its centre, `beyond` more of b and one to close the last node's support.
std::vector<double> graded_side(double D, int beyond, const Grading& g, const char* which) {
  const double r = g.growth, fine = g.fine;
  // Each growing cell is wider than a fine one, so no more of them than D / fine fit: a ratio just
  // above 1 (1.0000001 would grow for 1.4e7 cells) costs work in the side's length, not in the
  // ratio's closeness to 1. The sums are added in the same order as one by one.
  const double room = std::floor(D / fine);
  int K = 0;
  while (K < room && fine * std::pow(r, K + 1) <= g.largest * (1.0 + 1e-12)) ++K;
  std::vector<double> grown_to(static_cast<std::size_t>(K) + 1, 0.0);  // the first k growing cells' sum
  for (int k = 1; k <= K; ++k) grown_to[k] = grown_to[k - 1] + fine * std::pow(r, k);
  for (; K >= 0; --K) {
    const double grown = grown_to[K];
    const double c = fine * std::pow(r, K), rest = D - grown;
    if (rest <= 0.0) continue;
    const double P = std::round(rest / c + 0.5);
    const double b = rest / (P - 0.5);
    if (P < 4.0 || b > c * r * (1.0 + 1e-12) || b < c / r * (1.0 - 1e-12)) continue;
    std::vector<double> out;
    for (int k = 1; k <= K; ++k) out.push_back(fine * std::pow(r, k));
    out.insert(out.end(), static_cast<std::size_t>(P) + beyond + 1, b);
    return out;
  }
  throw std::invalid_argument(std::string("the ") + which + " end lies " + std::to_string(D) +
                              " m from the refined window: at least 3.5 fine cells (" + std::to_string(3.5 * fine) +
                              " m) must lie between them, or the window must reach past it");
}

bool on_lattice(double x, double reference, double fine) {
  const double n = (x - reference) / fine;
  return std::fabs(n - std::round(n)) < 1e-9;
}

}  // namespace

GradedAxis::GradedAxis(std::vector<double> knots) : knots_(std::move(knots)) {
  if (knots_.size() < 4) throw std::invalid_argument("a graded axis needs at least 4 knots");
  for (std::size_t k = 1; k < knots_.size(); ++k)
    if (!(knots_[k] > knots_[k - 1])) throw std::invalid_argument("a graded axis's knots must increase strictly");
  nodes_.resize(knots_.size() - 3);
  for (std::size_t i = 0; i < nodes_.size(); ++i) nodes_[i] = 0.5 * (knots_[i + 1] + knots_[i + 2]);
  // What splines_on_interval gives at t_j on interval j - 1 (slots 1, 2) or on interval j (slots 0,
  // 1), to the bit: at a knot its degree-1 quotients are exactly 0 and 1 and one pair is left.
  at_knot_.assign(2 * knots_.size(), 0.0);
  const double* t = knots_.data();
  for (std::size_t j = 1; j + 1 < knots_.size(); ++j) {
    const DoublePair n = DoublePair{t[j + 1] - t[j], t[j] - t[j - 1]} / DoublePair{t[j + 1] - t[j - 1], t[j + 1] - t[j - 1]};
    at_knot_[2 * j] = n[0];
    at_knot_[2 * j + 1] = n[1];
  }
}

int GradedAxis::interval(double x) const {
  return static_cast<int>(std::upper_bound(knots_.begin(), knots_.end(), x) - knots_.begin()) - 1;
}

int GradedAxis::interval(double x, int hint) const {
  const int last = static_cast<int>(knots_.size()) - 1;
  for (int k : {hint, hint + 1, hint - 1})  // t_k <= x < t_{k+1}: upper_bound's answer, found locally
    if (k >= 0 && k < last && knots_[k] <= x && x < knots_[k + 1]) return k;
  return interval(x);
}

int GradedAxis::node_at(double x, double tolerance) const {
  const auto it = std::lower_bound(nodes_.begin(), nodes_.end(), x - tolerance);
  return it != nodes_.end() && std::fabs(*it - x) <= tolerance ? static_cast<int>(it - nodes_.begin()) : -1;
}

int GradedAxis::cell(double x) const {
  const int i = static_cast<int>(std::upper_bound(nodes_.begin(), nodes_.end(), x) - nodes_.begin()) - 1;
  return std::clamp(i, 0, nodes() - 2);
}

double widest_domain(const GradedAxis& axis, double x, int hint) {
  const std::vector<double>& t = axis.knots();
  const int k = axis.interval(x, hint), last = static_cast<int>(t.size()) - 1;
  if (k < 1 || k + 2 > last) return 0.0;
  // Within [t_{k-1}, t_{k+1}] or within [t_k, t_{k+2}]: whichever leaves the wider domain, a
  // rounding's width inside it (x - l would otherwise round onto the next interval: a run stopped).
  constexpr double inside = 1.0 - 1e-12;
  return inside * std::max(std::min(x - t[k - 1], t[k + 1] - x), std::min(x - t[k], t[k + 2] - x));
}

bool graded_weights(const GradedAxis& axis, double x, double l, GradedWeights& out, int hint) {
  const double* t = axis.knots().data();
  const double a = x - l, b = x + l;
  const int ka = axis.interval(a, hint), kb = axis.interval(b, hint);
  const int last = static_cast<int>(axis.knots().size()) - 2;  // the last interval
  // Interval k carries N_{k-2} .. N_k: the first two and the last two intervals lack a node.
  if (!(ka >= 2 && kb <= last - 2 && kb - ka <= 1)) return false;
  out.first = ka - 2;
  std::fill(out.w, out.w + 4, 0.0);
  std::fill(out.dw, out.dw + 4, 0.0);
  // The average of the splines over [a, b]: Simpson's rule on each piece inside one interval,
  // exact for the quadratic pieces. The splines at the domain's ends give the slope too; at a
  // knot between the pieces they are the axis's own (GradedAxis::splines_at_knot).
  const double inv = 1.0 / (b - a);
  double at_a[3], at_b[3];
  const auto piece = [&](int k, double c, const double lo[3], double d, const double hi[3]) {
    double mid[3];
    splines_on_interval(t, k, 0.5 * (c + d), mid);
    const int slot = k - ka;
    for (int s = 0; s < 3; ++s) out.w[slot + s] += (d - c) / 6.0 * (lo[s] + 4.0 * mid[s] + hi[s]) * inv;
  };
  splines_on_interval(t, ka, a, at_a);
  splines_on_interval(t, kb, b, at_b);
  if (kb == ka) {
    piece(ka, a, at_a, b, at_b);
  } else {
    const double* knot = axis.splines_at_knot(kb);
    const double end_of_ka[3] = {0.0, knot[0], knot[1]}, start_of_kb[3] = {knot[0], knot[1], 0.0};
    piece(ka, a, at_a, t[kb], end_of_ka);
    piece(kb, t[kb], start_of_kb, b, at_b);
  }
  for (int s = 0; s < 3; ++s) {
    out.dw[s] -= at_a[s] * inv;
    out.dw[kb - ka + s] += at_b[s] * inv;
  }
  return true;
}

std::vector<double> graded_knots(const AxisEnd& lo, const AxisEnd& hi, double reference, double window_lo,
                                 double window_hi, const Grading& g) {
  const double fine = g.fine;
  if (!(fine > 0.0) || !(g.growth > 1.0) || !(g.largest >= fine) || !(lo.at < hi.at) || !(window_lo < window_hi))
    throw std::invalid_argument("a graded axis needs fine cells > 0, a growth ratio > 1, largest cells >= the fine "
                                "ones, and ordered ends and window");
  // The window's first and last knots on the lattice reference + (k + 1/2) fine.
  long long k_lo = static_cast<long long>(std::floor((window_lo - reference) / fine - 0.5 + 1e-9));
  long long k_hi = static_cast<long long>(std::ceil((window_hi - reference) / fine - 0.5 - 1e-9));
  const auto lattice = [&](long long k) { return reference + (static_cast<double>(k) + 0.5) * fine; };
  std::vector<double> lo_side, hi_side;
  if (lo.at >= lattice(k_lo) - 1e-9 * fine) {  // inside the window: fine cells through the end
    if (!on_lattice(lo.at, reference, fine))
      throw std::invalid_argument("the lower end (" + std::to_string(lo.at) + " m) lies inside the refined window " +
                                  "but not on a node of its fine cells");
    k_lo = std::llround((lo.at - reference) / fine) - lo.beyond - 2;
  } else {
    lo_side = graded_side(lattice(k_lo) - lo.at, lo.beyond, g, "lower");
  }
  if (hi.at <= lattice(k_hi) + 1e-9 * fine) {
    if (!on_lattice(hi.at, reference, fine))
      throw std::invalid_argument("the upper end (" + std::to_string(hi.at) + " m) lies inside the refined window " +
                                  "but not on a node of its fine cells");
    k_hi = std::llround((hi.at - reference) / fine) + hi.beyond + 1;
  } else {
    hi_side = graded_side(hi.at - lattice(k_hi), hi.beyond, g, "upper");
  }
  std::vector<double> knots;
  double x = lattice(k_lo);
  for (double d : lo_side) x -= d;
  for (auto it = lo_side.rbegin(); it != lo_side.rend(); ++it) {
    knots.push_back(x);
    x += *it;
  }
  for (long long k = k_lo; k <= k_hi; ++k) knots.push_back(lattice(k));
  x = lattice(k_hi);
  for (double d : hi_side) knots.push_back(x += d);
  return knots;
}

}  // namespace acst::mpm
