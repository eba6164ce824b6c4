#include "acst_sweep/case_labels.hpp"

#include <charconv>
#include <cmath>

#include <nlohmann/json.hpp>

namespace acst::mpm {

namespace {

// A value as a reader writes it: at most four significant digits, no trailing zeros.
std::string shown(double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v + 0.0, std::chars_format::general, 4);
  return std::string(buf, r.ptr);
}

std::string model_of(const SweepCase& c, const BodySpec& body) {
  for (const MaterialSpec& m : c.scene.materials) {
    if (m.name != body.material) continue;
    const nlohmann::json j = nlohmann::json::parse(m.json_text, nullptr, false);
    if (!j.is_object() || !j.contains("model") || !j["model"].is_string()) return "";
    const std::string model = j["model"];
    return model == "isotropic" ? "isotropic" : model == "ACST" ? "anisotropic" : model;
  }
  return "";
}

}  // namespace

std::vector<std::string> case_quantities(const SweepCase& c) {
  std::vector<std::string> q;
  if (c.scene.bodies.empty()) return q;
  const BodySpec& sand = c.scene.bodies.front();
  if (sand.relative_density) q.push_back("Dr = " + shown(100.0 * *sand.relative_density) + " %");
  else if (sand.void_ratio) q.push_back("e0 = " + shown(*sand.void_ratio));
  q.push_back("α = " + shown(sand.bedding_angle_deg) + "°");
  if (c.scene.footing) {
    q.push_back("β = " + shown(std::fabs(c.scene.footing->inclination_deg)) + "°");
    q.push_back("B = " + shown(c.scene.footing->width) + " m");
  }
  q.push_back("L = " + shown(sand.x_max - sand.x_min) + " m");
  if (const std::string m = model_of(c, sand); !m.empty()) q.push_back(m);
  return q;
}

CaseLabels case_labels(const std::vector<const SweepCase*>& cases) {
  CaseLabels out;
  std::vector<std::vector<std::string>> q;
  std::size_t n = 0;
  for (const SweepCase* c : cases) q.push_back(case_quantities(*c)), n = std::max(n, q.back().size());
  std::vector<bool> same(n, true);
  for (std::size_t k = 0; k < n; ++k)
    for (const std::vector<std::string>& r : q) same[k] = same[k] && k < r.size() && r[k] == q.front()[k];
  for (std::size_t k = 0; k < n && !q.empty(); ++k)
    if (same[k]) out.shared += (out.shared.empty() ? "" : ", ") + q.front()[k];
  for (std::size_t i = 0; i < cases.size(); ++i) {
    std::string legend;
    for (std::size_t k = 0; k < q[i].size(); ++k)
      if (!same[k]) legend += (legend.empty() ? "" : ", ") + q[i][k];
    out.legends.push_back(legend.empty() ? cases[i]->name : legend);
  }
  return out;
}

}  // namespace acst::mpm
