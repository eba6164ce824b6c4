#pragma once
// Butcher tableaux of the explicit schemes, low-order solution embedded for the error estimate.
#include <array>

#include "acst/integration/options.hpp"

namespace acst::integration {

struct Tableau {
  int stages;
  int error_order;  // order q of the embedded (lower) solution: step factor (STOL/R)^(1/(q+1))
  bool first_same_as_last;
  std::array<std::array<double, 7>, 7> a;
  std::array<double, 7> b;       // solution that is kept
  std::array<double, 7> b_low;   // embedded solution, for the error only
};

// Heun-Euler 2(1): Sloan's modified Euler.
inline constexpr Tableau modified_euler_tableau{2, 1, false, {{{0}, {1.0}}}, {0.5, 0.5}, {1.0, 0.0}};

// Bogacki-Shampine 3(2).
inline constexpr Tableau bogacki_shampine_tableau{
    4, 2, true,
    {{{0}, {0.5}, {0.0, 0.75}, {2.0 / 9.0, 1.0 / 3.0, 4.0 / 9.0}}},
    {2.0 / 9.0, 1.0 / 3.0, 4.0 / 9.0, 0.0},
    {7.0 / 24.0, 0.25, 1.0 / 3.0, 0.125}};

// Dormand-Prince 5(4).
inline constexpr Tableau dormand_prince_tableau{
    7, 4, true,
    {{{0},
      {1.0 / 5.0},
      {3.0 / 40.0, 9.0 / 40.0},
      {44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0},
      {19372.0 / 6561.0, -25360.0 / 2187.0, 64448.0 / 6561.0, -212.0 / 729.0},
      {9017.0 / 3168.0, -355.0 / 33.0, 46732.0 / 5247.0, 49.0 / 176.0, -5103.0 / 18656.0},
      {35.0 / 384.0, 0.0, 500.0 / 1113.0, 125.0 / 192.0, -2187.0 / 6784.0, 11.0 / 84.0}}},
    {35.0 / 384.0, 0.0, 500.0 / 1113.0, 125.0 / 192.0, -2187.0 / 6784.0, 11.0 / 84.0, 0.0},
    {5179.0 / 57600.0, 0.0, 7571.0 / 16695.0, 393.0 / 640.0, -92097.0 / 339200.0, 187.0 / 2100.0, 1.0 / 40.0}};

inline const Tableau& tableau_of(Scheme s) {
  switch (s) {
    case Scheme::rk23: return bogacki_shampine_tableau;
    case Scheme::rk45: return dormand_prince_tableau;
    default: return modified_euler_tableau;
  }
}

}  // namespace acst::integration
