#pragma once
// One axis of a graded background grid (docs/mpm.md, "The graded grid"): the knots
// t_0 < t_1 < ... of quadratic B-splines, node i standing for the spline N_i on t_i .. t_{i+3}
// and sitting at its Greville point (t_{i+1} + t_{i+2}) / 2, the centre of knot interval i + 1.
// On evenly spaced knots these are the uniform grid's B2 functions with nodes h apart. The
// weights are the splines averaged over a particle's undeformed domain [x - l, x + l] (B2GIMP on
// uneven knots): a sum of unity, linear fields reproduced exactly (the Greville points are the
// splines' linear coefficients), and a slope (N_i(x + l) - N_i(x - l)) / 2l.
#include <vector>

namespace acst::mpm {

class GradedAxis {
 public:
  GradedAxis() = default;
  // At least 4 knots, strictly increasing (std::invalid_argument otherwise).
  explicit GradedAxis(std::vector<double> knots);

  bool empty() const { return knots_.empty(); }
  int nodes() const { return static_cast<int>(nodes_.size()); }
  double node(int i) const { return nodes_[static_cast<std::size_t>(i)]; }
  const std::vector<double>& knots() const { return knots_; }
  // The knot interval k with t_k <= x < t_{k+1}; -1 left of the first knot, the last interval's
  // index + 1 from the last knot on.
  int interval(double x) const;
  // The same interval, looked for first at `hint` and its neighbours (a particle's interval of the
  // step before): a search of the knots only where x has moved further.
  int interval(double x, int hint) const;
  // The node within `tolerance` of x, or -1.
  int node_at(double x, double tolerance) const;
  // The node cell i with node(i) <= x < node(i + 1), clamped to the first and last cell.
  int cell(double x) const;
  // The splines N_{j-2}, N_{j-1} at an inner knot t_j (0 < j < knots - 1; the others are zero
  // there), worked out with the knots: where a particle's domain straddles t_j.
  const double* splines_at_knot(int j) const { return &at_knot_[2 * static_cast<std::size_t>(j)]; }

 private:
  std::vector<double> knots_, nodes_, at_knot_;
};

// The 4 nodes along a graded axis that can carry weight for a particle at x with domain
// half-width l (m): nodes first .. first + 3, the weights and dS/dx (per metre).
struct GradedWeights {
  int first;
  double w[4];
  double dw[4];
};

// The largest half-width of a domain at x that covers at most two knot intervals (the stencil's
// 4 nodes): at least half the interval x lies in, so an evenly spaced axis never clips a domain of
// up to half a cell.
// `hint`: where x was last (GradedAxis::interval); -1 for none.
double widest_domain(const GradedAxis& axis, double x, int hint = -1);

// False where the domain leaves the knots or covers more than two knot intervals.
// `hint`: x's knot interval, or near it (GradedAxis::interval); -1 for none.
bool graded_weights(const GradedAxis& axis, double x, double l, GradedWeights& out, int hint = -1);

// How an axis is graded (the scene's /grid/graded): cells of `fine` in a window, growing by at
// most `growth` per cell toward the ends, up to about `largest`.
struct Grading {
  double fine = 0.0, growth = 1.2, largest = 0.0;
};

// One end of an axis: a node at `at` (a wall or the grid's last row) and `beyond` more nodes
// past it (where a wall's mirror images fold in).
struct AxisEnd {
  double at = 0.0;
  int beyond = 0;
};

// The knots of an axis from `lo` to `hi`, fine cells of grading.fine on the lattice
// reference + (k + 1/2) fine over the window [window_lo, window_hi] (widened to the lattice),
// growing toward each end not inside the window, evenly spaced over the last 4 cells before an
// end and past it. An end inside the window must be on the lattice's nodes (reference + k fine).
// Throws std::invalid_argument, saying which end and why, where the ends cannot be met.
std::vector<double> graded_knots(const AxisEnd& lo, const AxisEnd& hi, double reference, double window_lo,
                                 double window_hi, const Grading& grading);

}  // namespace acst::mpm
