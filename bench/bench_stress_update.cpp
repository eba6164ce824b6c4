// Time per stress update of the explicit integrators (FE-1, ME, RK23, RK45 at STOL 1e-4) and of
// the C ABI (acst_update, ME; and, spun as an MPM host spins it, acst_rotate_state + acst_update
// against acst_update_rotated and acst_update_rotated_batch), guide set, single thread.
//   elastic: 1000 small unloading increments (1e-6 axial, reversed drained direction) from a
//            state inside the cone (dense sand, 2 % axial strain, then unloaded by 5e-4);
//   plastic: drained triaxial compression from 100 kPa, 1000 increments of 1e-4 axial strain
//            (to 10 %), dense (e0 0.67) and loose (e0 0.9), replayed as strain increments.
// Each figure is the median over 21 repetitions of the whole sequence, divided by its length.
// Usage: bench_stress_update [output_dir]   (writes stress_update.csv there; table on stdout)
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "acst.h"
#include "bench_support.hpp"

using namespace acst;
using integration::Scheme;

namespace {

constexpr int kRepetitions = 21;
constexpr int kElasticUpdates = 1000;

struct Sequence {
  State start;
  std::vector<Sym> increments;
};

struct Timing {
  double ns_per_update = 0.0;
  double substeps_per_update = 0.0;
  double evals_per_update = 0.0;
  int plastic_calls = 0;
  bool ok = true;
};

// Median over repetitions of the time of the whole sequence, per update.
Timing time_sequence(const Material& m, const Sequence& seq) {
  Timing t;
  std::vector<double> times;
  integration::Counters work;
  for (int rep = 0; rep < kRepetitions; ++rep) {
    State s = seq.start;
    int plastic = 0;
    bool ok = true;
    integration::Counters c;
    const double t0 = bench::now_seconds();
    for (const Sym& deps : seq.increments) {
      const integration::Report r = m.update(s, deps);
      ok &= r.status == integration::Status::ok;
      plastic += r.plastic;
      c += r.counters;
    }
    times.push_back(bench::now_seconds() - t0);
    if (rep == 0) {
      work = c;
      t.plastic_calls = plastic;
      t.ok = ok;
    }
  }
  const double n = seq.increments.size();
  t.ns_per_update = bench::median(times) / n * 1e9;
  t.substeps_per_update = (work.substeps_accepted + work.substeps_rejected) / n;
  t.evals_per_update = work.rate_evaluations / n;
  return t;
}

// The same sequence through the C ABI (tension positive, engineering shear): acst_update alone,
// or as an MPM host calls it, each increment after a small spin about z (acst_rotate_state and
// acst_update, or both in one acst_update_rotated).
// acst_update_rotated_batch takes 8 copies of the point in lock step (the library's SIMD lanes
// take what is theirs: docs/c-abi.md, "Many points at once"); its figure is per point and update.
enum class AbiCall { update, rotate_then_update, update_rotated, update_rotated_batch };
constexpr int kBatchCopies = 8;

struct AbiTiming {
  double ns_per_update = 0.0;
  double max_difference = 0.0;  // |stress_abi + stress_cpp| / |stress_cpp| at the end (acst_update alone)
  std::array<double, 6> end_stress{};
  bool ok = true;
};

AbiTiming time_abi(const acst_model* model, const Material& m, const Sequence& seq, bool with_tangent,
                   AbiCall call = AbiCall::update) {
  AbiTiming t;
  double statev0[ACST_NSTATV], stress0[6];
  Sym start_abi = -seq.start.stress;  // the C ABI convention: tension positive
  const double dir[3] = {1.0, 0.0, 0.0};
  // The C ABI builds its own initial state; start from the same stress, void ratio and fabric
  // by reproducing the state variables (layout: docs/c-abi.md, state_layout.hpp).
  for (int i = 0; i < 6; ++i) stress0[i] = start_abi[i];
  acst_status st = acst_initial_state(statev0, stress0, model, stress0, seq.start.void_ratio, dir);
  if (st.code != ACST_OK) {
    std::fprintf(stderr, "acst_initial_state: %s\n", st.message);
    t.ok = false;
    return t;
  }
  for (int i = 0; i < 6; ++i) statev0[i] = seq.start.fabric[i];
  statev0[6] = seq.start.void_ratio;
  statev0[7] = seq.start.H;
  statev0[8] = seq.start.substep_hint;
  std::vector<std::array<double, 6>> dstrain(seq.increments.size());
  for (size_t k = 0; k < seq.increments.size(); ++k)
    for (int i = 0; i < 6; ++i) dstrain[k][i] = -seq.increments[k][i] * (i < 3 ? 1.0 : 2.0);
  std::vector<double> times;
  double stress[6 * kBatchCopies], statev[ACST_NSTATV * kBatchCopies], tangent[36];
  double spins[9 * kBatchCopies];
  std::vector<std::array<double, 6 * kBatchCopies>> dstrains(dstrain.size());
  const int copies = call == AbiCall::update_rotated_batch ? kBatchCopies : 1;
  double* const D = with_tangent ? tangent : nullptr;
  const double a = 1e-4;  // radians per increment, an MPM particle's spin under a footing
  const double spin[9] = {std::cos(a), -std::sin(a), 0.0, std::sin(a), std::cos(a), 0.0, 0.0, 0.0, 1.0};
  for (int c = 0; c < kBatchCopies; ++c) std::copy(spin, spin + 9, spins + 9 * c);
  for (size_t k = 0; k < dstrain.size(); ++k)
    for (int c = 0; c < kBatchCopies; ++c) std::copy(dstrain[k].begin(), dstrain[k].end(), dstrains[k].begin() + 6 * c);
  for (int rep = 0; rep < kRepetitions; ++rep) {
    for (int c = 0; c < copies; ++c) {
      std::copy(stress0, stress0 + 6, stress + 6 * c);
      std::copy(statev0, statev0 + ACST_NSTATV, statev + ACST_NSTATV * c);
    }
    const double t0 = bench::now_seconds();
    for (size_t k = 0; k < dstrain.size(); ++k) {
      const auto& d = dstrain[k];
      switch (call) {
        case AbiCall::update: st = acst_update(stress, statev, D, nullptr, model, d.data()); break;
        case AbiCall::rotate_then_update:
          st = acst_rotate_state(stress, statev, model, spin);
          if (st.code == ACST_OK) st = acst_update(stress, statev, D, nullptr, model, d.data());
          break;
        case AbiCall::update_rotated: st = acst_update_rotated(stress, statev, D, nullptr, model, spin, d.data()); break;
        case AbiCall::update_rotated_batch:
          st = acst_update_rotated_batch(stress, 6, statev, ACST_NSTATV, nullptr, nullptr, model, kBatchCopies, spins,
                                         dstrains[k].data());
          break;
      }
      t.ok &= st.code == ACST_OK;
    }
    times.push_back(bench::now_seconds() - t0);
  }
  t.ns_per_update = bench::median(times) / (dstrain.size() * copies) * 1e9;
  std::copy(stress, stress + 6, t.end_stress.begin());
  State s = seq.start;
  for (const Sym& deps : seq.increments) m.update(s, deps);
  Sym abi_end;
  for (int i = 0; i < 6; ++i) abi_end[i] = -stress[i];
  t.max_difference = norm(abi_end - s.stress) / norm(s.stress);
  return t;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const std::string out = bench::output_dir(
        argc, argv,
        "usage: bench_stress_update [--help] [DIR]\n"
        "Cost of one stress update per scheme (guide set, STOL 1e-4); writes DIR/stress_update.csv\n"
        "(default DIR: <source>/bench/results).\n");
    const Material guide = bench::guide_material();

    // Plastic sequences: drained triaxial, 1000 x 1e-4 axial.
    std::vector<std::pair<std::string, Sequence>> plastic;
    for (auto [name, e0] : {std::pair<const char*, double>{"dense", 0.67}, {"loose", 0.9}}) {
      Sequence seq;
      seq.start = bench::isotropic_sample(guide, 100.0, e0);
      seq.increments = bench::drained_triaxial_strain_path(guide, seq.start, 1e-4, 1000);
      plastic.emplace_back(name, seq);
    }
    // Elastic sequence: dense sand loaded to 2 % axial strain, unloaded by 5e-4, then 1000
    // further unloading increments of 1e-6 (all inside the cone).
    Sequence elastic;
    {
      State s = bench::isotropic_sample(guide, 100.0, 0.67);
      const std::vector<Sym> load = bench::drained_triaxial_strain_path(guide, s, 1e-3, 20);
      s = bench::replay(bench::with_integrator(guide, Scheme::rk45, 1e-10), s, load).states.back();
      const Sym direction = load.back() / load.back()[0];
      guide.update(s, -5e-4 * direction);
      elastic.start = s;
      elastic.increments.assign(kElasticUpdates, -1e-6 * direction);
    }

    struct Row {
      std::string scheme;
      Timing elastic, dense, loose;
    };
    std::vector<Row> rows;
    const std::vector<std::pair<std::string, Material>> materials = {
        {"FE-1", bench::with_integrator(guide, Scheme::forward_euler, 1e-4, 1)},
        {"ME", bench::with_integrator(guide, Scheme::modified_euler, 1e-4)},
        {"RK23", bench::with_integrator(guide, Scheme::rk23, 1e-4)},
        {"RK45", bench::with_integrator(guide, Scheme::rk45, 1e-4)},
    };
    for (const auto& [name, m] : materials) {
      std::fprintf(stderr, "timing %s ...\n", name.c_str());
      rows.push_back({name, time_sequence(m, elastic), time_sequence(m, plastic[0].second),
                      time_sequence(m, plastic[1].second)});
      if (rows.back().elastic.plastic_calls != 0) std::fprintf(stderr, "warning: an 'elastic' update was plastic\n");
    }

    // C ABI, ME at STOL 1e-4 (the guide file's integrator section).
    acst_model* model = nullptr;
    const acst_status st = acst_model_create(&model, bench::guide_json().c_str());
    if (st.code != ACST_OK) throw std::runtime_error(std::string("acst_model_create: ") + st.message);
    const Material me = materials[1].second;
    const AbiTiming abi_el = time_abi(model, me, elastic, false);
    const AbiTiming abi_dense = time_abi(model, me, plastic[0].second, false);
    const AbiTiming abi_loose = time_abi(model, me, plastic[1].second, false);
    const AbiTiming abi_dense_t = time_abi(model, me, plastic[0].second, true);
    const AbiTiming abi_el_t = time_abi(model, me, elastic, true);
    std::array<AbiTiming, 3> two_calls, one_call, batch;  // elastic, dense, loose
    const Sequence* sequences[3] = {&elastic, &plastic[0].second, &plastic[1].second};
    for (int k = 0; k < 3; ++k) {
      two_calls[k] = time_abi(model, me, *sequences[k], false, AbiCall::rotate_then_update);
      one_call[k] = time_abi(model, me, *sequences[k], false, AbiCall::update_rotated);
      batch[k] = time_abi(model, me, *sequences[k], false, AbiCall::update_rotated_batch);
    }
    acst_model_destroy(model);

    std::printf("Stress update cost, guide set, STOL 1e-4, median of %d repetitions, single thread\n", kRepetitions);
    std::printf("elastic: %d unloading increments of 1e-6 inside the cone; plastic: drained triaxial, 1000 x 1e-4 "
                "axial from 100 kPa\n\n",
                kElasticUpdates);
    std::printf("| scheme | ns/update elastic | ns/update plastic dense | ns/update plastic loose | substeps/update "
                "(dense, loose) | rate evals/update (dense, loose) |\n");
    std::printf("|---|---:|---:|---:|---:|---:|\n");
    bench::CsvTable csv(
        "scheme,ns_elastic,ns_plastic_dense,ns_plastic_loose,substeps_dense,substeps_loose,evals_dense,evals_loose,"
        "evals_elastic,status");
    const auto tenth = [](double v) { return std::round(10.0 * v) / 10.0; };
    const auto thousandth = [](double v) { return std::round(1000.0 * v) / 1000.0; };
    for (const Row& r : rows) {
      const bool ok = r.elastic.ok && r.dense.ok && r.loose.ok;
      std::printf("| %s | %.0f | %.0f | %.0f | %.2f, %.2f | %.2f, %.2f |%s\n", r.scheme.c_str(),
                  r.elastic.ns_per_update, r.dense.ns_per_update, r.loose.ns_per_update, r.dense.substeps_per_update,
                  r.loose.substeps_per_update, r.dense.evals_per_update, r.loose.evals_per_update,
                  ok ? "" : " FAILED CALLS");
      csv.cell(r.scheme).cell(tenth(r.elastic.ns_per_update)).cell(tenth(r.dense.ns_per_update));
      csv.cell(tenth(r.loose.ns_per_update)).cell(thousandth(r.dense.substeps_per_update));
      csv.cell(thousandth(r.loose.substeps_per_update)).cell(thousandth(r.dense.evals_per_update));
      csv.cell(thousandth(r.loose.evals_per_update)).cell(thousandth(r.elastic.evals_per_update));
      csv.cell(ok ? "ok" : "failed").end_row();
    }
    const bool abi_ok = abi_el.ok && abi_dense.ok && abi_loose.ok && abi_dense_t.ok && abi_el_t.ok;
    std::printf("| C ABI acst_update, ME | %.0f | %.0f | %.0f | (as ME) | (as ME) |%s\n", abi_el.ns_per_update,
                abi_dense.ns_per_update, abi_loose.ns_per_update, abi_ok ? "" : " FAILED CALLS");
    std::printf("| C ABI acst_update, ME, with tangent | %.0f | %.0f | - | (as ME) | (as ME) |\n",
                abi_el_t.ns_per_update, abi_dense_t.ns_per_update);
    csv.cell("C_ABI_ME").cell(tenth(abi_el.ns_per_update)).cell(tenth(abi_dense.ns_per_update));
    csv.cell(tenth(abi_loose.ns_per_update));
    for (int k = 0; k < 5; ++k) csv.blank();  // no substep or evaluation counts
    csv.cell(abi_ok ? "ok" : "failed").end_row();
    csv.cell("C_ABI_ME_tangent").cell(tenth(abi_el_t.ns_per_update)).cell(tenth(abi_dense_t.ns_per_update));
    for (int k = 0; k < 6; ++k) csv.blank();  // no loose figure, no counts
    csv.cell(abi_ok ? "ok" : "failed").end_row();
    bool same_numbers = true;
    for (const auto* calls : {&two_calls, &one_call, &batch}) {
      const bool rotated_ok = (*calls)[0].ok && (*calls)[1].ok && (*calls)[2].ok;
      const char* name = calls == &one_call ? "acst_update_rotated"
                         : calls == &batch  ? "acst_update_rotated_batch (8 points)"
                                            : "acst_rotate_state + acst_update";
      const char* column = calls == &one_call ? "C_ABI_ME_update_rotated"
                           : calls == &batch  ? "C_ABI_ME_update_rotated_batch"
                                              : "C_ABI_ME_rotate_then_update";
      std::printf("| C ABI %s, ME, spun 1e-4 rad per update | %.0f | %.0f | %.0f | (as ME) | (as ME) |%s\n", name,
                  (*calls)[0].ns_per_update, (*calls)[1].ns_per_update, (*calls)[2].ns_per_update,
                  rotated_ok ? "" : " FAILED CALLS");
      csv.cell(column).cell(tenth((*calls)[0].ns_per_update));
      csv.cell(tenth((*calls)[1].ns_per_update)).cell(tenth((*calls)[2].ns_per_update));
      for (int k = 0; k < 5; ++k) csv.blank();  // no substep or evaluation counts
      csv.cell(rotated_ok ? "ok" : "failed").end_row();
    }
    for (int k = 0; k < 3; ++k)
      same_numbers &= one_call[k].end_stress == two_calls[k].end_stress && batch[k].end_stress == one_call[k].end_stress;
    csv.publish(out + "/stress_update.csv");
    std::printf("\nC ABI end stress vs C++ end stress (relative): elastic %.1e, dense %.1e, loose %.1e\n",
                abi_el.max_difference, abi_dense.max_difference, abi_loose.max_difference);
    std::printf("Spun sequences, acst_update_rotated against acst_rotate_state + acst_update and against the batch: %s\n",
                same_numbers ? "the same end stress bit for bit" : "END STRESSES DIFFER");
    const Row& me_row = rows[1];
    std::printf("Targets (ME, STOL 1e-4): plastic <= 2000 ns: dense %s (%.0f), loose %s (%.0f); elastic <= 200 ns: %s "
                "(%.0f)\n",
                me_row.dense.ns_per_update <= 2000 ? "met" : "MISSED", me_row.dense.ns_per_update,
                me_row.loose.ns_per_update <= 2000 ? "met" : "MISSED", me_row.loose.ns_per_update,
                me_row.elastic.ns_per_update <= 200 ? "met" : "MISSED", me_row.elastic.ns_per_update);
    std::printf("wrote %s/stress_update.csv\n", out.c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_stress_update: %s\n", e.what());
    return 1;
  }
  return 0;
}
