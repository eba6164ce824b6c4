/* acst.h: C ABI of the ACST sand model library (anisotropic critical state theory,
 * Li & Dafalias 2012, multiaxial form of Gao et al. 2014) and its isotropic reduction, with three
 * closed-form verification materials behind the same handle.
 *
 * MODEL KINDS ("model" in the JSON of acst_model_create; acst_model_kind tells them apart):
 *   "ACST", "isotropic": the sand model; "parameters" as in docs/c-abi.md, optional
 *       "integrator"; 10 state variables (fabric F11..F23, void ratio, H, substep hint, resets).
 *   "linear_elastic": {"E": kPa > 0, "nu": in (-1, 0.5)}; no state variables.
 *   "von_mises": perfectly plastic, associated, radial return; {"E", "nu", and exactly one of
 *       "yield_stress" (sigma_y, kPa > 0) or "undrained_shear_strength" (s_u, kPa > 0, sigma_y =
 *       sqrt(3) s_u: max shear s_u in plane strain)}; 1 state variable, equivalent_plastic_strain.
 *   "drucker_prager": perfectly plastic cone matched to Mohr-Coulomb in plane strain, return
 *       onto the cone or its apex; {"E", "nu", "friction_angle_deg" (phi in [0, 60)), "cohesion"
 *       (c, kPa >= 0; not both zero), optional "dilation_angle_deg" (psi in [0, phi], default
 *       phi: associated)}; 1 state variable, equivalent_plastic_strain.
 *   The three verification kinds take no "integrator" key.
 *
 * CONVENTION AT THIS INTERFACE (the Abaqus UMAT convention; the C++ API differs):
 *   - Voigt order 11, 22, 33, 12, 13, 23;
 *   - strain components are ENGINEERING shear strains (gamma_12 = 2 eps_12);
 *   - TENSION POSITIVE for stress and strain;
 *   - stress in kPa, density in kg/m^3, wave speed in m/s;
 *   - the tangent is row-major, tangent[6*i + j] = d stress_i / d strain_j, in this convention.
 * State variables (statev) are stored in the model's own frame and sign (compression positive):
 * they are state, not stress; ask acst_state_name for their names.
 *
 * Rules: no function aborts, exits, prints or keeps global state. A model handle is immutable
 * after creation, so one handle may be used from many threads at once; each thread passes its
 * own stress and state arrays. Every function returns an acst_status whose message says what went
 * wrong. Mutable arguments come first.
 * ACST_OK means every output is finite and physical (void ratio in (0, 2.97), H >= 0,
 * p >= p_min, every stress component at most 1e100 kPa in size, tangent finite; docs/c-abi.md
 * "The OK rule"); any other status leaves the caller's stress and state unchanged.
 */
#ifndef ACST_H
#define ACST_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct acst_model acst_model; /* opaque */

enum acst_status_code {
  ACST_OK = 0,
  ACST_STEP_REDUCTION = 1,     /* integration failed; retry with strain increment x suggested_step_factor */
  ACST_INVALID_INPUT = 2,      /* bad JSON, parameter, argument or non-finite strain */
  ACST_NONPHYSICAL_STATE = 3,  /* non-finite or non-physical stress/state on entry */
  ACST_INTERNAL_ERROR = 4      /* unexpected failure (out of memory, ...) */
};

typedef struct acst_status {
  int code;                       /* an acst_status_code */
  double suggested_step_factor;   /* < 1 with ACST_STEP_REDUCTION, else 1 */
  char message[256];              /* empty when code == ACST_OK */
} acst_status;

/* Work and guard counters of one update call (summed over points in the batch form). */
typedef struct acst_counters {
  int substeps_accepted;
  int substeps_rejected;
  int rate_evaluations;
  int crossing_iterations;
  int unload_reload;
  int guard_pressure_floor;
  int guard_small_R;
  int guard_lode_clamp;
  int guard_h_floor;
  int guard_uniqueness;
  int pressure_floor_resets;
  int plastic; /* 1 if the call ended on a plastic substep (count of such points in a batch) */
} acst_counters;

#define ACST_NTENS 6
#define ACST_NSTATV 10 /* state size of ACST/isotropic, the largest of any kind */
#define ACST_NDIAGNOSTICS 13

/* Creates a model from JSON text:
 *   {"model": "ACST"|"isotropic"|"linear_elastic"|"von_mises"|"drucker_prager", "parameters": {...}, "integrator": {...}}
 * (see docs/c-abi.md; "model" defaults to "ACST"). On failure *model is NULL and the message
 * names the JSON path and the allowed range. */
acst_status acst_model_create(acst_model** model, const char* json_text);
void acst_model_destroy(acst_model* model);

/* "ACST", "isotropic", "linear_elastic", "von_mises" or "drucker_prager" (NULL for a NULL handle). */
const char* acst_model_kind(const acst_model* model);

/* Number of state variables of this model (10, 0 or 1; 0 for a NULL handle) and the name of
 * variable i (NULL if out of range). Where the size is 0, every statev argument may be NULL. */
int acst_state_size(const acst_model* model);
const char* acst_state_name(const acst_model* model, int i);

/* Initial stress (this interface's convention) and state from a stress, a void ratio and the
 * deposition direction (normal to the bedding planes, any non-zero length).
 * stress_out may alias stress0. The verification kinds copy the stress, zero the state and ignore
 * void ratio and direction (which may be NULL); von_mises and drucker_prager give
 * ACST_NONPHYSICAL_STATE for a stress outside their yield surface (relative tolerance 1e-9). */
acst_status acst_initial_state(double* statev, double* stress_out, const acst_model* model, const double* stress0,
                               double void_ratio, const double* deposition_direction);

/* Deposition direction b (unit) for a bedding angle alpha in degrees: the angle between b and
 * the major loading axis, b = cos(alpha) e_major + sin(alpha) e_minor (axes 0, 1, 2). For
 * the plane-strain footing frame (x horizontal, y vertical) use major = 1, minor = 0 and a
 * negative alpha sense by passing minor_sign = -1: b = (-sin alpha, cos alpha, 0). */
acst_status acst_bedding_direction(double* b, double alpha_degrees, int major_axis, int minor_axis,
                                   double minor_sign);

/* Void ratio from a relative density Dr in [0, 1]: e = e_max - Dr (e_max - e_min). Sand models
 * only (ACST_INVALID_INPUT otherwise). */
acst_status acst_void_ratio_from_relative_density(double* void_ratio, const acst_model* model,
                                                  double relative_density);

/* THE UPDATE: one entry point for any number of points, with optional per-point inputs and
 * outputs (MGIS's pattern: a new input or output is a field of this data view, not a new
 * function). Zero-initialise it (acst_batch b = {0};), then fill what the host has. Strides are
 * in doubles between consecutive points and must be at least the width given in brackets where
 * the array is present and n > 0; a pointer left NULL is an absent input or an unwanted output
 * (its stride is then not read). A new field is appended at the end: a host rebuilt against the
 * new header, whose view is zero-initialised, leaves it absent. */
typedef struct acst_batch {
  size_t n; /* number of points */
  /* In and out, required (statev may be NULL where acst_state_size is 0). */
  double* stress;         /* point i's 6 at stress + i stress_stride [6] */
  size_t stress_stride;
  double* statev;         /* point i's at statev + i statev_stride [acst_state_size] */
  size_t statev_stride;
  /* In, required: the strain increment (engineering shear; in the turned frame if rotation). */
  const double* dstrain;  /* [6] */
  size_t dstrain_stride;
  /* Optional inputs (NULL: absent). */
  const double* rotation; /* each point turned by its 3x3 row-major Q first, as acst_update_rotated [9] */
  size_t rotation_stride;
  const double* offset;   /* nonlocal offsets, as acst_update_nonlocal [acst_nonlocal_size] */
  size_t offset_stride;
  /* Optional outputs (NULL: not wanted). */
  double* tangent;        /* point i's 36, row-major, written where its update is OK [36] */
  size_t tangent_stride;
  int* point_status;              /* n codes, one per point */
  acst_counters* point_counters;  /* n structs, one per point (zero for a point refused on its input) */
  acst_counters* counters;        /* one struct: the sum over the points (plastic: how many) */
  size_t* first_failure;          /* the index of the first failed point, n where none failed */
} acst_batch;

/* Updates the n points of the view: each point's stress and state turned by its rotation (if
 * given) and then updated over its strain increment with its nonlocal offsets (if given), every
 * point's numbers, code and counters those of acst_update_rotated_nonlocal (rotation given) or
 * acst_update_nonlocal (not) on it, to the last bit. All points are attempted; a failed point is
 * left as it came (stress, state and tangent); a point whose rotation is not a proper rotation or
 * whose offsets are out of range fails with ACST_INVALID_INPUT. The returned status is the first
 * failed point's, its message starting with "point i: ". A NULL view or model, a required pointer
 * that is NULL, a stride below its width, or strides that reach past the largest array a host can
 * hold give ACST_INVALID_INPUT before any point is touched: nothing is written. The sand kinds
 * update the points of the common kinds of update several at a time in SIMD registers where a
 * rotation is given and no tangent asked for (docs/c-abi.md, "Many points at once").
 * acst_update, acst_update_batch, acst_update_rotated, acst_update_rotated_batch and their
 * _nonlocal forms (below) are thin wrappers that fill a view and call this; their numbers,
 * codes, counters and messages are as they were (a short stride's message now names it). */
acst_status acst_update_points(const acst_batch* points, const acst_model* model);

/* One stress update (a wrapper of acst_update_points): stress[6] and statev[acst_state_size] in
 * and out, dstrain[6] in. tangent (36 doubles) and counters are optional (NULL); counters are
 * written after the update, failed or not. On any failure stress and statev are left unchanged,
 * and bad input (a NULL pointer, bad offsets) writes nothing. The verification kinds return the
 * elastic matrix or the consistent elastoplastic tangent of the return, and zero counters except
 * plastic (1 if von_mises or drucker_prager yielded). Hosts with large rotations call
 * acst_rotate_state first, or acst_update_rotated. */
acst_status acst_update(double* stress, double* statev, double* tangent, acst_counters* counters,
                        const acst_model* model, const double* dstrain);

/* The same over n points (a wrapper of acst_update_points without rotation, offsets or tangent);
 * strides are in doubles between consecutive points (statev_stride at least acst_state_size).
 * point_status (n ints, optional) receives each point's code; counters (optional) the sum over
 * the points; the returned status is the first failure, its message naming the point. All points
 * are attempted. */
acst_status acst_update_batch(double* stress, size_t stress_stride, double* statev, size_t statev_stride,
                              int* point_status, acst_counters* counters, const acst_model* model, size_t n,
                              const double* dstrain, size_t dstrain_stride);

/* P-wave speed sqrt((K + 4G/3)/rho) in m/s from the current elastic stiffness (from E and nu for
 * the verification kinds), for explicit time steps; density in kg/m^3. With the option
 * elastic_anisotropy, the fastest direction's bound sqrt((K + 4G/3) P_max^4 / rho)
 * (docs/model.md section 2). */
acst_status acst_wave_speed(double* speed, const acst_model* model, const double* stress, const double* statev,
                            double density);

/* Derived quantities (ACST_NDIAGNOSTICS doubles, named by acst_diagnostic_name):
 * p, q, R, sin3theta, psi, zeta, A, fabric_norm, e_c, D, Kp, G, K (stresses kPa, compression
 * positive). The loading direction is the one of the current stress ratio. The verification
 * kinds fill p, q, G, K and set the sand-specific entries to NaN. */
acst_status acst_diagnostics(double* out, const acst_model* model, const double* stress, const double* statev);
const char* acst_diagnostic_name(int i);

/* Objective rotation of one point: stress <- Q stress Q^T and every tensorial state variable
 * likewise (the fabric, slots 0-5, of ACST/isotropic; none for the verification kinds).
 * rotation: 3x3 proper orthogonal, row-major (finite, |Q Q^T - I| < 1e-8, det Q > 0, else
 * ACST_INVALID_INPUT with stress and statev unchanged). Hosts with large rotations (MPM, updated
 * Lagrangian FE) call it before each acst_update with the incremental rotation of the step,
 * e.g. Hughes-Winget Q = (I - W/2)^-1 (I + W/2) with W = dt skew(L), L the velocity gradient,
 * then update with the strain increment dt sym(L) (engineering shear). */
acst_status acst_rotate_state(double* stress, double* statev, const acst_model* model, const double* rotation);

/* acst_rotate_state and then acst_update in one call (a wrapper of acst_update_points with a
 * rotation), with their numbers: the state turned by
 * rotation, then updated over dstrain (given in the turned frame). It fails wherever the two calls
 * fail: a turned state that acst_rotate_state refuses and acst_update alone would take (a sand
 * state with a tensile mean stress, a state variable that is not a number) is
 * ACST_NONPHYSICAL_STATE here too, so that after ACST_STEP_REDUCTION the retry below can always
 * start. On any failure stress and statev are left as they came, unrotated: the host retries from
 * its own state (or turns it with acst_rotate_state and subdivides dstrain). OK vouches for the
 * updated state as acst_update's does; the rotated intermediate is never handed out. */
acst_status acst_update_rotated(double* stress, double* statev, double* tangent, acst_counters* counters,
                                const acst_model* model, const double* rotation, const double* dstrain);

/* acst_update_rotated over n points (a wrapper of acst_update_points with rotation_stride 9 and
 * dstrain_stride 6): point i's stress, statev, rotation (9 doubles, row-major)
 * and dstrain at stress + i stress_stride, statev + i statev_stride, rotation + 9 i and
 * dstrain + 6 i. Every point's numbers are acst_update_rotated's on it, to the last bit: the sand
 * kinds update several points at once in SIMD registers where a point's update is the common
 * one (loaded on the yield surface, one substep; docs/c-abi.md). point_status (n ints, optional)
 * receives each point's code, point_counters (n structs, optional) each point's counters. The
 * returned status is the first failure, its message naming the point; a failed point is left as
 * it came, unrotated, and the others are updated. */
acst_status acst_update_rotated_batch(double* stress, size_t stress_stride, double* statev, size_t statev_stride,
                                      int* point_status, acst_counters* point_counters, const acst_model* model,
                                      size_t n, const double* rotation, const double* dstrain);

/* NONLOCAL REGULARISATION (docs/c-abi.md, "Nonlocal regularisation"). A softening sand
 * localises in bands as thin as a host's discretisation allows, so the answer of a boundary-value
 * problem moves with the mesh. A host that regularises it averages each point's local quantities
 * over a neighbourhood of an internal length of its own choosing and hands every point the
 * offsets "averaged minus its own" at the start of the increment; the model takes the averaged
 * quantities where its softening comes from and keeps stress, strain and all else local.
 *   ACST, isotropic: one quantity, "void_ratio": the state parameter psi = e - e_c(p), which sets
 *       the dilatancy and the peak, becomes psi + offset over the increment (e evolving with the
 *       increment's own volume change), but no looser than critical (psi + offset > 0) unless
 *       the point is looser itself: min(psi + offset, max(psi, 0)); the elasticity and the
 *       hardening keep e.
 *   linear_elastic, von_mises, drucker_prager: none (nothing softens); an offset argument is ignored.
 * acst_nonlocal_size: the number of quantities (0 or 1; 0 for a NULL handle); acst_nonlocal_name
 * their names (NULL out of range); acst_nonlocal_local: a point's local values (acst_nonlocal_size
 * doubles) from its stress and state, which must be finite. */
int acst_nonlocal_size(const acst_model* model);
const char* acst_nonlocal_name(const acst_model* model, int i);
acst_status acst_nonlocal_local(double* local, const acst_model* model, const double* stress, const double* statev);

/* acst_update, acst_update_rotated and acst_update_rotated_batch with each point's offsets
 * (wrappers of acst_update_points with offset):
 * acst_nonlocal_size doubles a point (point i's at offset + i acst_nonlocal_size in the batch),
 * each finite and smaller than 2.97 in size (else ACST_INVALID_INPUT). offset NULL, or offsets of
 * zero, give the local functions' numbers to the last bit; everything else is as there. */
acst_status acst_update_nonlocal(double* stress, double* statev, double* tangent, acst_counters* counters,
                                 const acst_model* model, const double* dstrain, const double* offset);
acst_status acst_update_rotated_nonlocal(double* stress, double* statev, double* tangent, acst_counters* counters,
                                         const acst_model* model, const double* rotation, const double* dstrain,
                                         const double* offset);
acst_status acst_update_rotated_batch_nonlocal(double* stress, size_t stress_stride, double* statev,
                                               size_t statev_stride, int* point_status, acst_counters* point_counters,
                                               const acst_model* model, size_t n, const double* rotation,
                                               const double* dstrain, const double* offset);

/* Reproducers: the element-test scene (JSON text, docs/element-tests.md) that replays one
 * update with `acst_element FILE`: the material written out in full, the whole state, the
 * strain increment as six strain-controlled rows of one increment. Write it for an update that
 * failed (before retrying) and a user can replay and report it. Sand models only (ACST,
 * isotropic); the verification kinds give ACST_INVALID_INPUT.
 * Buffer rules: *length holds the size of `buffer` on entry and the size the text needs
 * (terminating NUL included) on return. With buffer NULL only the size is returned (ACST_OK);
 * a buffer too small gives ACST_INVALID_INPUT and nothing is written. */
acst_status acst_reproducer(char* buffer, size_t* length, const acst_model* model, const double* stress,
                            const double* statev, const double* dstrain);

/* acst_reproducer of a nonlocal update (acst_update_nonlocal's offset, or NULL): the scene holds
 * the offset in its initial state, which acst_element applies to every increment. */
acst_status acst_reproducer_nonlocal(char* buffer, size_t* length, const acst_model* model, const double* stress,
                                     const double* statev, const double* dstrain, const double* offset);

/* The same for a umat_ host, from exactly what umat_ receives (NTENS 6 or 4, PROPS as for
 * umat_, DROT may be NULL): the fabric turned as umat_ turns it, so the scene replays what
 * umat_ computed. */
acst_status acst_umat_reproducer(char* buffer, size_t* length, const double* stress, const double* statev,
                                 const double* dstran, int ntens, const double* props, int nprops, const double* drot);

/* umat_'s work, with its status: what umat_ does to STRESS, STATEV, DDSDDE and PNEWDT, and the
 * reason of a failure in the returned status (umat_ itself has no way to say it). A host glue
 * that can print (the CalculiX glue of materials/calculix/) calls this and reports the message.
 * The failure protocol that umat_ follows (docs/c-abi.md, "umat_ and its hosts"):
 *   - a good update leaves PNEWDT as it came;
 *   - a step reduction sets PNEWDT to a factor in [0.01, 0.9]: the suggested factor, or a smaller
 *     request already in PNEWDT (PNEWDT <= 0 on entry means "no request yet", as CalculiX passes -1);
 *   - an unrecoverable failure (bad PROPS, NTENS or NSTATV, a non-physical state on entry, a
 *     non-finite strain) sets ACST_UMAT_UNRECOVERABLE_PNEWDT, so the host cuts back below its
 *     minimum increment and stops with its own message;
 *   - on any failure STRESS and STATEV are unchanged and DDSDDE holds a finite, positive definite
 *     elastic tangent of the start state (NTENS x NTENS, column-major); only an NTENS other than
 *     6 or 4 or a NULL array leaves DDSDDE unwritten (its size is unknown). */
#define ACST_UMAT_UNRECOVERABLE_PNEWDT 1e-6
acst_status acst_umat(double* stress, double* statev, double* ddsdde, const double* dstran, int ntens, int nstatv,
                      const double* props, int nprops, const double* drot, double* pnewdt);

/* Abaqus-compatible entry point for the ACST model only (standard UMAT argument list; see
 * docs/c-abi.md for the PROPS and STATEV layouts). NTENS = 6 (3-D) or 4 (plane strain /
 * axisymmetric: 11, 22, 33, 12). The failure protocol is acst_umat's (above). */
void umat_(double* stress, double* statev, double* ddsdde, double* sse, double* spd, double* scd, double* rpl,
           double* ddsddt, double* drplde, double* drpldt, const double* stran, const double* dstran,
           const double* time, const double* dtime, const double* temp, const double* dtemp, const double* predef,
           const double* dpred, const char* cmname, const int* ndi, const int* nshr, const int* ntens,
           const int* nstatv, const double* props, const int* nprops, const double* coords, const double* drot,
           double* pnewdt, const double* celent, const double* dfgrd0, const double* dfgrd1, const int* noel,
           const int* npt, const int* layer, const int* kspt, const int* kstep, const int* kinc,
           size_t cmname_length);

#ifdef __cplusplus
}
#endif

#endif /* ACST_H */
