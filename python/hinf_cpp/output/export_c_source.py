"""The fixed C99 sources of an exported controller (:mod:`hinf_cpp.output.export_c` writes them
with the design's tables beside them). Private: the text is the arithmetic of
``OnlineController::step`` (cpp/src/control/online_controller.cpp, online_estimator.cpp) for the
cases the export supports, written out without Eigen.
"""

from __future__ import annotations

# hinf_controller.h after its configuration block (sizes written by the exporter).
HEADER_BODY = r"""
/* What hinf_controller_step() did (OnlineController's StepStatus). */
typedef enum {
  HINF_STATUS_OK = 0,           /* a command was computed (report.measurement: the measurement) */
  HINF_STATUS_REFUSED = 1,      /* t_now not finite or earlier than the last call's: the command held */
  HINF_STATUS_PAST_HORIZON = 2, /* t_now >= HINF_T_END, where the design ends: the command held */
  HINF_STATUS_NOT_RESET = 3,    /* before hinf_controller_reset(): u left as it is */
  HINF_STATUS_LOST = 4          /* the estimate is not finite: the command held until reset */
} hinf_status;

/* What became of the measurement (MeasurementUse). Anything but USED: the estimate was predicted. */
typedef enum {
  HINF_MEASUREMENT_USED = 0,
  HINF_MEASUREMENT_MISSING = 1,    /* none given (NULL) */
  HINF_MEASUREMENT_STALE = 2,      /* older than max_age at t_now, or than the commands remembered */
  HINF_MEASUREMENT_DUPLICATE = 3,  /* not newer than the last one used */
  HINF_MEASUREMENT_FUTURE = 4,     /* t_meas > t_now */
  HINF_MEASUREMENT_NOT_FINITE = 5  /* t_meas or a component is NaN or infinite */
} hinf_measurement_use;

/* The report of the last step (StepReport). */
typedef struct {
  hinf_status status;
  hinf_measurement_use measurement;
  int saturated;          /* a bound u_min / u_max was active */
  int rate_limited;       /* the rate limit was active */
  double rho_sigma_z;     /* output feedback: rho(Sigma Z) at t_now (NaN: state feedback) */
  int coupling_violated;  /* output feedback: rho(Sigma Z) >= gamma^2 */
} hinf_report;

/* Counts since the reset (OnlineCounts). */
typedef struct {
  long steps, used, predicted, refused, past_horizon, lost, saturated, rate_limited, coupling_violated;
  double largest_command;       /* max |u_i| over the commands computed */
  double coupling_violation_t;  /* t_now of the first coupling violation (NaN: none) */
  double largest_rho;           /* max rho(Sigma Z) / gamma^2 */
} hinf_counts;

/* The controller of one vehicle: owned by the caller (static, on the stack, anywhere); read
   report and counts, leave the rest to the functions. */
typedef struct {
  int is_reset, is_lost;
  double t_last;       /* the last call's t_now (s) */
  double t_meas_last;  /* the last measurement used (s) */
  double t_x;          /* the time of the estimate x (s) */
  double t_held;       /* the time of the command held (s) */
  double x[HINF_N];    /* the estimate of q_e = q - q_d at t_x */
  double u_held[HINF_M];
  /* The applied commands: a ring of HINF_HISTORY entries, oldest first from history_start. */
  double history_t[HINF_HISTORY];
  double history_u[HINF_HISTORY][HINF_M];
  int history_start, history_size;
  /* Output feedback: the filter's Sigma at t_x, and the estimate at the last measurement used. */
  double Sigma[HINF_N * HINF_N];
  double x_anchor[HINF_N];
  double Sigma_anchor[HINF_N * HINF_N];
  hinf_report report;
  hinf_counts counts;
} hinf_controller_state;

/* Prepares a state: every step answers HINF_STATUS_NOT_RESET until hinf_controller_reset(). */
void hinf_controller_init(hinf_controller_state *state);

/* Starts at time t (s, in [HINF_T0, HINF_T_END)) from the state q (HINF_N numbers; output
   feedback: the initial estimate, Sigma = Sigma0), holding u_held (HINF_M numbers; NULL: u_d(t)
   within the bounds). Returns 0, or -1 for a t outside the horizon or a value that is not finite
   (the state is then unchanged). */
int hinf_controller_reset(hinf_controller_state *state, double t, const double *q, const double *u_held);

/* One sample: the measurement (HINF_MEASUREMENT_SIZE numbers: q, or y = C q with output
   feedback; NULL: none) taken at t_meas (s), the command for t_now (s) into u (HINF_M numbers),
   to apply now and hold. Returns state->report.status. No heap, no I/O. */
hinf_status hinf_controller_step(hinf_controller_state *state, double t_now, const double *measurement, double t_meas,
                                 double *u);

/* The desired state q_d(t) of the design (HINF_N numbers; t in [HINF_T0, HINF_T_END]): the
   tabulated samples, cubic Hermite in between. */
void hinf_controller_desired_state(double t, double *q_d);

#endif /* HINF_CONTROLLER_H */
"""

# hinf_controller_tables.h: the design's data, private to the folder.
TABLES_HEADER = r"""/* The design's tables (hinf_controller_tables.c, written by the exporter). Private. */
#ifndef HINF_CONTROLLER_TABLES_H
#define HINF_CONTROLLER_TABLES_H

#include "hinf_controller.h"

/* k = 0 .. HINF_STEPS at t_k = min(t0 + k T, tf); matrices row-major. */
extern const double hinf_table_A[HINF_STEPS + 1][HINF_N * HINF_N];   /* A_e(t_k) */
extern const double hinf_table_B[HINF_STEPS + 1][HINF_N * HINF_M];   /* B_e(t_k) */
extern const double hinf_table_q_d[HINF_STEPS + 1][HINF_N];          /* q_d(t_k) */
extern const double hinf_table_dq_d[HINF_STEPS + 1][HINF_N];         /* dq_d/dt(t_k) */
extern const double hinf_table_K[HINF_STEPS][HINF_M * HINF_N];       /* the gains K_k */
#if HINF_P > 0
extern const double hinf_table_DDt[HINF_STEPS + 1][HINF_N * HINF_N]; /* D_e(t_k) D_e(t_k)' */
extern const double hinf_table_Z[HINF_STEPS + 1][HINF_N * HINF_N];   /* Z(t_k), or M_k */
extern const double hinf_C[HINF_P * HINF_N];            /* y = C q */
extern const double hinf_CtRinv[HINF_N * HINF_P];       /* C' R^-1, R = N / hold */
extern const double hinf_CtRinvC[HINF_N * HINF_N];      /* C' R^-1 C */
extern const double hinf_S_predict[HINF_N * HINF_N];    /* gamma^-2 Q */
extern const double hinf_Sigma0[HINF_N * HINF_N];
extern const int hinf_heading_row;                      /* the row of C measuring the heading, or -1 */
#endif
extern const double hinf_gamma;       /* +inf: LQR */
extern const double hinf_inv_gamma2;  /* gamma^-2 (0 for LQR) */
extern const double hinf_max_age;     /* s */
extern const int hinf_compensate_delay;
extern const int hinf_heading_index;  /* the state's heading, or -1 */
extern const int hinf_has_u_min, hinf_has_u_max, hinf_has_rate_max;
extern const double hinf_u_min[HINF_M], hinf_u_max[HINF_M], hinf_rate_max[HINF_M];

/* u_d(t) (HINF_M numbers): the desired inputs' signals as the design defines them. */
void hinf_u_d(double t, double *u_d);

#endif /* HINF_CONTROLLER_TABLES_H */
"""

SOURCE = r"""/* The online controller's step (hinf_cpp's OnlineController::step) for the exported design:
   state feedback with delay compensation, or output feedback with the sampled measurement update
   (the estimator (35) and filter (36) along the linearization between measurements, a jump at
   each measurement). C99, libm only, no heap. See README.md. */
#include "hinf_controller.h"

#include <math.h>
#include <string.h>

#include "hinf_controller_tables.h"

#define NN (HINF_N * HINF_N)
#define HINF_PI 3.14159265358979323846

/* The prediction's classical Runge-Kutta steps are at most this long (s), as hinf_cpp's. */
static const double max_substep = 0.005;

static double wrap_angle(double angle) {
  double wrapped = remainder(angle, 2.0 * HINF_PI); /* in [-pi, pi] */
  if (wrapped <= -HINF_PI) wrapped += 2.0 * HINF_PI;
  return wrapped;
}

static double clamp(double v, double lo, double hi) { return v < lo ? lo : (hi < v ? hi : v); }

/* The sample k that holds t, and where t lies in [t_k, t_{k+1}] (theta in [0, 1]). */
static int locate(double t, double *theta) {
  const double position = (t - HINF_T0) / HINF_PERIOD;
  const double k = clamp(floor(position), 0.0, (double)(HINF_STEPS - 1));
  *theta = clamp(position - k, 0.0, 1.0);
  return (int)k;
}

/* The sample of the law at t (hinf_cpp's rounding: a time a hair before t_k is t_k's). */
static int sample_of(double t) {
  return (int)clamp(floor((t - HINF_T0) / HINF_PERIOD + 1e-9), 0.0, (double)(HINF_STEPS - 1));
}

/* q_d(t): cubic Hermite between the samples (exact at them). */
static void desired_state(double t, double *q_d) {
  double s;
  const int k = locate(t, &s);
  const double s2 = s * s, s3 = s2 * s;
  const double h00 = 2.0 * s3 - 3.0 * s2 + 1.0, h10 = s3 - 2.0 * s2 + s, h01 = -2.0 * s3 + 3.0 * s2, h11 = s3 - s2;
  int i;
  for (i = 0; i < HINF_N; ++i)
    q_d[i] = h00 * hinf_table_q_d[k][i] + h10 * HINF_PERIOD * hinf_table_dq_d[k][i] + h01 * hinf_table_q_d[k + 1][i] +
             h11 * HINF_PERIOD * hinf_table_dq_d[k + 1][i];
}

void hinf_controller_desired_state(double t, double *q_d) { desired_state(t, q_d); }

static void tracking_error(const double *q, const double *q_d, double *q_e) {
  int i;
  for (i = 0; i < HINF_N; ++i) q_e[i] = q[i] - q_d[i];
  if (hinf_heading_index >= 0) q_e[hinf_heading_index] = wrap_angle(q_e[hinf_heading_index]);
}

/* The linearization at one time, linear between the samples. */
typedef struct {
  double at;
  double A[NN], B[HINF_N * HINF_M];
#if HINF_P > 0
  double DDt[NN], Z[NN];
#endif
} linearization;

static void interpolate(linearization *L, double t) {
  double theta;
  int k, i;
  if (t == L->at) return; /* RK4 asks twice for the midpoint */
  L->at = t;
  k = locate(t, &theta);
  for (i = 0; i < NN; ++i) L->A[i] = (1.0 - theta) * hinf_table_A[k][i] + theta * hinf_table_A[k + 1][i];
  for (i = 0; i < HINF_N * HINF_M; ++i) L->B[i] = (1.0 - theta) * hinf_table_B[k][i] + theta * hinf_table_B[k + 1][i];
#if HINF_P > 0
  for (i = 0; i < NN; ++i) L->DDt[i] = (1.0 - theta) * hinf_table_DDt[k][i] + theta * hinf_table_DDt[k + 1][i];
  for (i = 0; i < NN; ++i) L->Z[i] = (1.0 - theta) * hinf_table_Z[k][i] + theta * hinf_table_Z[k + 1][i];
#endif
}

/* out = a b (a: r x c, b: c x k), row-major. */
static void multiply(const double *a, const double *b, int r, int c, int k, double *out) {
  int i, j, l;
  for (i = 0; i < r; ++i)
    for (j = 0; j < k; ++j) {
      double sum = 0.0;
      for (l = 0; l < c; ++l) sum += a[i * c + l] * b[l * k + j];
      out[i * k + j] = sum;
    }
}

#if HINF_P > 0
/* The Cholesky factor L of a (n x n, lower, row-major); 0 when a is not positive definite. */
static int cholesky(const double *a, double *L) {
  int i, j, k;
  memset(L, 0, sizeof(double) * NN);
  for (j = 0; j < HINF_N; ++j) {
    double d = a[j * HINF_N + j];
    for (k = 0; k < j; ++k) d -= L[j * HINF_N + k] * L[j * HINF_N + k];
    if (!(d > 0.0)) return 0;
    d = sqrt(d);
    L[j * HINF_N + j] = d;
    for (i = j + 1; i < HINF_N; ++i) {
      double v = a[i * HINF_N + j];
      for (k = 0; k < j; ++k) v -= L[i * HINF_N + k] * L[j * HINF_N + k];
      L[i * HINF_N + j] = v / d;
    }
  }
  return 1;
}

/* a^-1 from its Cholesky factor L. */
static void cholesky_inverse(const double *L, double *inverse) {
  int c, i, k;
  for (c = 0; c < HINF_N; ++c) {
    double y[HINF_N];
    for (i = 0; i < HINF_N; ++i) { /* L y = e_c */
      double v = i == c ? 1.0 : 0.0;
      for (k = 0; k < i; ++k) v -= L[i * HINF_N + k] * y[k];
      y[i] = v / L[i * HINF_N + i];
    }
    for (i = HINF_N - 1; i >= 0; --i) { /* L' x = y */
      double v = y[i];
      for (k = i + 1; k < HINF_N; ++k) v -= L[k * HINF_N + i] * inverse[k * HINF_N + c];
      inverse[i * HINF_N + c] = v / L[i * HINF_N + i];
    }
  }
}

static void symmetrize(double *a) {
  int i, j;
  for (i = 0; i < HINF_N; ++i)
    for (j = i + 1; j < HINF_N; ++j) {
      const double mean = 0.5 * (a[i * HINF_N + j] + a[j * HINF_N + i]);
      a[i * HINF_N + j] = mean;
      a[j * HINF_N + i] = mean;
    }
}

/* x = a^-1 b by Gaussian elimination with partial pivoting (a is overwritten). */
static void solve(double *a, double *b, double *x) {
  int i, j, k;
  for (k = 0; k < HINF_N; ++k) {
    int pivot = k;
    for (i = k + 1; i < HINF_N; ++i)
      if (fabs(a[i * HINF_N + k]) > fabs(a[pivot * HINF_N + k])) pivot = i;
    if (pivot != k) {
      for (j = 0; j < HINF_N; ++j) {
        const double swap = a[k * HINF_N + j];
        a[k * HINF_N + j] = a[pivot * HINF_N + j];
        a[pivot * HINF_N + j] = swap;
      }
      {
        const double swap = b[k];
        b[k] = b[pivot];
        b[pivot] = swap;
      }
    }
    for (i = k + 1; i < HINF_N; ++i) {
      const double factor = a[i * HINF_N + k] / a[k * HINF_N + k];
      for (j = k; j < HINF_N; ++j) a[i * HINF_N + j] -= factor * a[k * HINF_N + j];
      b[i] -= factor * b[k];
    }
  }
  for (i = HINF_N - 1; i >= 0; --i) {
    double v = b[i];
    for (j = i + 1; j < HINF_N; ++j) v -= a[i * HINF_N + j] * x[j];
    x[i] = v / a[i * HINF_N + i];
  }
}

/* The largest eigenvalue of the symmetric a (overwritten), by cyclic Jacobi rotations. */
static double largest_eigenvalue(double *a) {
  int sweep, p, q, k;
  double largest;
  for (sweep = 0; sweep < 60; ++sweep) {
    double off = 0.0, scale = 0.0;
    for (p = 0; p < HINF_N; ++p)
      for (q = 0; q < HINF_N; ++q) {
        if (p != q) off += a[p * HINF_N + q] * a[p * HINF_N + q];
        scale += a[p * HINF_N + q] * a[p * HINF_N + q];
      }
    if (off <= 1e-30 * scale) break;
    for (p = 0; p < HINF_N - 1; ++p)
      for (q = p + 1; q < HINF_N; ++q) {
        const double apq = a[p * HINF_N + q];
        double theta, t, c, s;
        if (apq == 0.0) continue;
        theta = (a[q * HINF_N + q] - a[p * HINF_N + p]) / (2.0 * apq);
        t = (theta >= 0.0 ? 1.0 : -1.0) / (fabs(theta) + sqrt(theta * theta + 1.0));
        c = 1.0 / sqrt(t * t + 1.0);
        s = t * c;
        for (k = 0; k < HINF_N; ++k) { /* columns p, q */
          const double akp = a[k * HINF_N + p], akq = a[k * HINF_N + q];
          a[k * HINF_N + p] = c * akp - s * akq;
          a[k * HINF_N + q] = s * akp + c * akq;
        }
        for (k = 0; k < HINF_N; ++k) { /* rows p, q */
          const double apk = a[p * HINF_N + k], aqk = a[q * HINF_N + k];
          a[p * HINF_N + k] = c * apk - s * aqk;
          a[q * HINF_N + k] = s * apk + c * aqk;
        }
      }
  }
  largest = a[0];
  for (k = 1; k < HINF_N; ++k)
    if (a[k * HINF_N + k] > largest) largest = a[k * HINF_N + k];
  return largest;
}

/* rho(Sigma Z) = the largest eigenvalue of L' Z L, Sigma = L L' (+inf: Sigma not positive
   definite). */
static double rho(const double *Sigma, const double *Z) {
  double L[NN], ZL[NN], LtZL[NN];
  int i, j, k;
  if (!cholesky(Sigma, L)) return INFINITY;
  multiply(Z, L, HINF_N, HINF_N, HINF_N, ZL);
  for (i = 0; i < HINF_N; ++i)
    for (j = 0; j < HINF_N; ++j) {
      double sum = 0.0;
      for (k = 0; k < HINF_N; ++k) sum += L[k * HINF_N + i] * ZL[k * HINF_N + j];
      LtZL[i * HINF_N + j] = sum;
    }
  return largest_eigenvalue(LtZL);
}
#endif

/* The prediction of the error (state feedback), or (35) and (36) without a measurement (output
   feedback), at t with the command u. */
static void derivative(linearization *L, double t, const double *x, const double *Sigma, const double *u, double *dx,
                       double *dSigma) {
  double u_d[HINF_M], ue[HINF_M], Bue[HINF_N];
  int i;
  interpolate(L, t);
  hinf_u_d(t, u_d);
  for (i = 0; i < HINF_M; ++i) ue[i] = u[i] - u_d[i];
  multiply(L->A, x, HINF_N, HINF_N, 1, dx);
  multiply(L->B, ue, HINF_N, HINF_M, 1, Bue);
  for (i = 0; i < HINF_N; ++i) dx[i] += Bue[i];
#if HINF_P > 0
  {
    double Zx[HINF_N], DDtZx[HINF_N], AS[NN], SpS[NN], SSpS[NN];
    int j;
    /* + gamma^-2 D_e D_e' Z q_hat: the worst-case disturbance the design assumes */
    multiply(L->Z, x, HINF_N, HINF_N, 1, Zx);
    multiply(L->DDt, Zx, HINF_N, HINF_N, 1, DDtZx);
    for (i = 0; i < HINF_N; ++i) dx[i] += hinf_inv_gamma2 * DDtZx[i];
    /* dSigma = A Sigma + Sigma A' + D D' + Sigma gamma^-2 Q Sigma */
    multiply(L->A, Sigma, HINF_N, HINF_N, HINF_N, AS);
    for (i = 0; i < HINF_N; ++i)
      for (j = 0; j < HINF_N; ++j)
        dSigma[i * HINF_N + j] = AS[i * HINF_N + j] + AS[j * HINF_N + i] + L->DDt[i * HINF_N + j];
    multiply(hinf_S_predict, Sigma, HINF_N, HINF_N, HINF_N, SpS);
    multiply(Sigma, SpS, HINF_N, HINF_N, HINF_N, SSpS);
    for (i = 0; i < NN; ++i) dSigma[i] += SSpS[i];
  }
#else
  (void)Sigma;
  (void)dSigma;
#endif
}

/* Classical Runge-Kutta from s to end in `substeps` equal steps with the command u held. */
static void integrate(linearization *L, double s, double end, int substeps, const double *u, double *x, double *Sigma) {
  const double h = (end - s) / substeps;
  double k1[HINF_N], k2[HINF_N], k3[HINF_N], k4[HINF_N], xs[HINF_N];
#if HINF_P > 0
  double S1[NN], S2[NN], S3[NN], S4[NN], Ss[NN];
#else
  double *S1 = 0, *S2 = 0, *S3 = 0, *S4 = 0, *Ss = 0;
#endif
  int step, i;
  for (step = 0; step < substeps; ++step) {
    const double a = s + step * h, mid = a + 0.5 * h, b = step + 1 == substeps ? end : a + h;
    const double dt = b - a;
    derivative(L, a, x, Sigma, u, k1, S1);
    for (i = 0; i < HINF_N; ++i) xs[i] = x[i] + 0.5 * dt * k1[i];
#if HINF_P > 0
    for (i = 0; i < NN; ++i) Ss[i] = Sigma[i] + 0.5 * dt * S1[i];
#endif
    derivative(L, mid, xs, Ss, u, k2, S2);
    for (i = 0; i < HINF_N; ++i) xs[i] = x[i] + 0.5 * dt * k2[i];
#if HINF_P > 0
    for (i = 0; i < NN; ++i) Ss[i] = Sigma[i] + 0.5 * dt * S2[i];
#endif
    derivative(L, mid, xs, Ss, u, k3, S3);
    for (i = 0; i < HINF_N; ++i) xs[i] = x[i] + dt * k3[i];
#if HINF_P > 0
    for (i = 0; i < NN; ++i) Ss[i] = Sigma[i] + dt * S3[i];
#endif
    derivative(L, b, xs, Ss, u, k4, S4);
    for (i = 0; i < HINF_N; ++i) x[i] += (dt / 6.0) * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
#if HINF_P > 0
    for (i = 0; i < NN; ++i) Sigma[i] += (dt / 6.0) * (S1[i] + 2.0 * S2[i] + 2.0 * S3[i] + S4[i]);
    symmetrize(Sigma); /* keeps Sigma symmetric against round-off */
#endif
  }
}

/* The history entry whose command is applied at t (the latest entry with time <= t). */
static int entry_at(const hinf_controller_state *st, double t) {
  int i;
  for (i = st->history_size - 1; i > 0; --i) {
    const int slot = (st->history_start + i) % HINF_HISTORY;
    if (st->history_t[slot] <= t) return slot;
  }
  return st->history_start;
}

/* Until when the command of that entry is applied: the next entry's time, at most t. */
static double command_end(const hinf_controller_state *st, int entry, double t) {
  const int next = (entry - st->history_start + HINF_HISTORY) % HINF_HISTORY + 1;
  double next_t;
  if (next >= st->history_size) return t;
  next_t = st->history_t[(st->history_start + next) % HINF_HISTORY];
  return next_t < t ? next_t : t;
}

static void remember(hinf_controller_state *st, double t, const double *u) {
  int slot;
  if (st->history_size > 0) {
    const int newest = (st->history_start + st->history_size - 1) % HINF_HISTORY;
    if (st->history_t[newest] == t) { /* the same time again: replaces */
      memcpy(st->history_u[newest], u, sizeof(double) * HINF_M);
      return;
    }
  }
  if (st->history_size < HINF_HISTORY) {
    slot = (st->history_start + st->history_size) % HINF_HISTORY;
    ++st->history_size;
  } else {
    slot = st->history_start;
    st->history_start = (st->history_start + 1) % HINF_HISTORY;
  }
  st->history_t[slot] = t;
  memcpy(st->history_u[slot], u, sizeof(double) * HINF_M);
}

/* The estimate predicted from t_x to t with the commands applied. */
static void predict_to(hinf_controller_state *st, linearization *L, double t) {
  double s = st->t_x;
  while (s < t) {
    const int entry = entry_at(st, s);
    const double end = command_end(st, entry, t);
    int substeps = (int)ceil((end - s) / max_substep - 1e-9);
    if (substeps < 1) substeps = 1;
    integrate(L, s, end, substeps, st->history_u[entry], st->x, st->Sigma);
    s = end;
  }
  if (t > st->t_x) st->t_x = t;
}

#if HINF_P > 0
/* The sampled measurement update at t: Sigma+ = (Sigma^-1 + C' R^-1 C)^-1,
   q_hat+ = q_hat + [I - gamma^-2 Sigma+ Z]^-1 Sigma+ C' R^-1 (y_e - C q_hat). */
static void update(hinf_controller_state *st, linearization *L, double t, const double *y_e) {
  double Lf[NN], information[NN], innovation[HINF_P], CtRi[HINF_N], r[HINF_N], SZ[NN], gain[NN], dx[HINF_N];
  int i;
  interpolate(L, t);
  if (!cholesky(st->Sigma, Lf)) {
    for (i = 0; i < HINF_N; ++i) st->x[i] = NAN;
    return;
  }
  cholesky_inverse(Lf, information);
  for (i = 0; i < NN; ++i) information[i] += hinf_CtRinvC[i];
  if (!cholesky(information, Lf)) {
    for (i = 0; i < HINF_N; ++i) st->x[i] = NAN;
    return;
  }
  cholesky_inverse(Lf, st->Sigma);
  symmetrize(st->Sigma);
  multiply(hinf_C, st->x, HINF_P, HINF_N, 1, innovation);
  for (i = 0; i < HINF_P; ++i) innovation[i] = y_e[i] - innovation[i];
  if (hinf_heading_row >= 0) innovation[hinf_heading_row] = wrap_angle(innovation[hinf_heading_row]);
  multiply(hinf_CtRinv, innovation, HINF_N, HINF_P, 1, CtRi);
  multiply(st->Sigma, CtRi, HINF_N, HINF_N, 1, r);
  multiply(st->Sigma, L->Z, HINF_N, HINF_N, HINF_N, SZ);
  for (i = 0; i < NN; ++i) gain[i] = (i % (HINF_N + 1) == 0 ? 1.0 : 0.0) - hinf_inv_gamma2 * SZ[i];
  solve(gain, r, dx);
  for (i = 0; i < HINF_N; ++i) st->x[i] += dx[i];
}
#endif

void hinf_controller_init(hinf_controller_state *state) {
  memset(state, 0, sizeof(*state));
  state->report.status = HINF_STATUS_NOT_RESET;
  state->report.measurement = HINF_MEASUREMENT_MISSING;
  state->report.rho_sigma_z = NAN;
  state->counts.coupling_violation_t = NAN;
}

int hinf_controller_reset(hinf_controller_state *state, double t, const double *q, const double *u_held) {
  double q_d[HINF_N];
  int i;
  if (!(isfinite(t) && t >= HINF_T0 && t < HINF_T_END)) return -1;
  for (i = 0; i < HINF_N; ++i)
    if (!isfinite(q[i])) return -1;
  for (i = 0; u_held != 0 && i < HINF_M; ++i)
    if (!isfinite(u_held[i])) return -1;
  desired_state(t, q_d);
  tracking_error(q, q_d, state->x);
  if (u_held == 0) {
    hinf_u_d(t, state->u_held);
    for (i = 0; i < HINF_M; ++i) {
      if (hinf_has_u_min && state->u_held[i] < hinf_u_min[i]) state->u_held[i] = hinf_u_min[i];
      if (hinf_has_u_max && state->u_held[i] > hinf_u_max[i]) state->u_held[i] = hinf_u_max[i];
    }
  } else {
    memcpy(state->u_held, u_held, sizeof(double) * HINF_M);
  }
  state->t_x = state->t_held = state->t_last = state->t_meas_last = t;
  state->history_start = state->history_size = 0;
#if HINF_P > 0
  state->t_meas_last = -INFINITY; /* the state given is an estimate: a measurement at t is new */
  memcpy(state->Sigma, hinf_Sigma0, sizeof(double) * NN);
  memcpy(state->x_anchor, state->x, sizeof(double) * HINF_N);
  memcpy(state->Sigma_anchor, state->Sigma, sizeof(double) * NN);
#endif
  remember(state, t, state->u_held);
  memset(&state->counts, 0, sizeof(state->counts));
  state->counts.coupling_violation_t = NAN;
  state->is_reset = 1;
  state->is_lost = 0;
  return 0;
}

static hinf_status hold(hinf_controller_state *st, hinf_status status, double *u) {
  memcpy(u, st->u_held, sizeof(double) * HINF_M);
  st->report.status = status;
  return status;
}

hinf_status hinf_controller_step(hinf_controller_state *st, double t_now, const double *measurement, double t_meas,
                                 double *u) {
  linearization L;
  hinf_report *report = &st->report;
  hinf_measurement_use use = HINF_MEASUREMENT_USED;
  double u_ff[HINF_M], command[HINF_M], oldest_command, t_law, dt;
  int late, k, i, j, finite;
  report->status = HINF_STATUS_NOT_RESET;
  report->measurement = HINF_MEASUREMENT_MISSING;
  report->saturated = report->rate_limited = report->coupling_violated = 0;
  report->rho_sigma_z = NAN;
  if (!st->is_reset) return HINF_STATUS_NOT_RESET;
  ++st->counts.steps;
  if (st->is_lost) {
    ++st->counts.lost;
    return hold(st, HINF_STATUS_LOST, u);
  }
  if (!isfinite(t_now) || t_now < st->t_last) {
    ++st->counts.refused;
    return hold(st, HINF_STATUS_REFUSED, u);
  }
  if (t_now >= HINF_T_END) {
    ++st->counts.past_horizon;
    return hold(st, HINF_STATUS_PAST_HORIZON, u);
  }

  /* The measurement. */
  oldest_command = st->history_t[st->history_start];
  if (measurement == 0) {
    use = HINF_MEASUREMENT_MISSING;
  } else {
    finite = isfinite(t_meas);
    for (i = 0; i < HINF_MEASUREMENT_SIZE && finite; ++i) finite = isfinite(measurement[i]);
    if (!finite)
      use = HINF_MEASUREMENT_NOT_FINITE;
    else if (t_meas > t_now)
      use = HINF_MEASUREMENT_FUTURE;
    else if (t_meas <= st->t_meas_last)
      use = HINF_MEASUREMENT_DUPLICATE;
    else if (t_now - t_meas > hinf_max_age || t_meas < oldest_command ||
             (HINF_P > 0 && t_meas < st->t_x && st->t_meas_last < oldest_command))
      use = HINF_MEASUREMENT_STALE;
  }
  report->measurement = use;
  report->status = HINF_STATUS_OK;

  /* The law acts on the estimate at t_now; without delay compensation, on q_e(t_meas). */
  L.at = NAN;
  late = use == HINF_MEASUREMENT_USED && !hinf_compensate_delay;
  t_law = late ? t_meas : t_now;
  k = sample_of(t_law);
  hinf_u_d(t_law, u_ff);
  if (use == HINF_MEASUREMENT_USED) {
    double q_d[HINF_N];
#if HINF_P > 0
    double y_e[HINF_P];
    /* From the last measurement's estimate when t_meas is earlier than the estimate's time. */
    if (t_meas < st->t_x) {
      memcpy(st->x, st->x_anchor, sizeof(double) * HINF_N);
      memcpy(st->Sigma, st->Sigma_anchor, sizeof(double) * NN);
      st->t_x = st->t_meas_last;
    }
    predict_to(st, &L, t_meas);
    desired_state(t_meas, q_d);
    multiply(hinf_C, q_d, HINF_P, HINF_N, 1, y_e);
    for (i = 0; i < HINF_P; ++i) y_e[i] = measurement[i] - y_e[i];
    if (hinf_heading_row >= 0) y_e[hinf_heading_row] = wrap_angle(y_e[hinf_heading_row]);
    update(st, &L, t_meas, y_e);
    memcpy(st->x_anchor, st->x, sizeof(double) * HINF_N);
    memcpy(st->Sigma_anchor, st->Sigma, sizeof(double) * NN);
#else
    desired_state(t_meas, q_d);
    tracking_error(measurement, q_d, st->x);
    st->t_x = t_meas;
#endif
    st->t_meas_last = t_meas;
    ++st->counts.used;
  } else {
    ++st->counts.predicted;
  }
  if (late) multiply(hinf_table_K[k], st->x, HINF_M, HINF_N, 1, command);
  predict_to(st, &L, t_now);
  if (!late) multiply(hinf_table_K[k], st->x, HINF_M, HINF_N, 1, command);
  finite = 1;
  for (i = 0; i < HINF_M; ++i) {
    command[i] = u_ff[i] - command[i];
    finite = finite && isfinite(command[i]);
  }
#if HINF_P > 0
  for (i = 0; i < NN; ++i) finite = finite && isfinite(st->Sigma[i]);
#endif
  if (!finite) {
    st->is_lost = 1;
    ++st->counts.lost;
    return hold(st, HINF_STATUS_LOST, u);
  }
#if HINF_P > 0
  {
    const double gamma2 = hinf_gamma * hinf_gamma;
    double r;
    interpolate(&L, t_now);
    r = rho(st->Sigma, L.Z);
    report->rho_sigma_z = r;
    report->coupling_violated = !(r < gamma2);
    st->counts.coupling_violated += report->coupling_violated;
    if (report->coupling_violated && isnan(st->counts.coupling_violation_t)) st->counts.coupling_violation_t = t_now;
    if (isfinite(gamma2) && r / gamma2 > st->counts.largest_rho) st->counts.largest_rho = r / gamma2;
  }
#endif

  /* The limits: the rate from the command held, then the bounds. */
  dt = t_now - st->t_held;
  for (j = 0; j < HINF_M; ++j) {
    double v = command[j], bounded;
    if (hinf_has_rate_max && isfinite(hinf_rate_max[j])) {
      const double step = hinf_rate_max[j] * dt;
      const double limited = clamp(v, st->u_held[j] - step, st->u_held[j] + step);
      if (limited != v) report->rate_limited = 1;
      v = limited;
    }
    bounded = clamp(v, hinf_has_u_min ? hinf_u_min[j] : -INFINITY, hinf_has_u_max ? hinf_u_max[j] : INFINITY);
    if (bounded != v) report->saturated = 1;
    u[j] = bounded;
    st->u_held[j] = bounded;
    if (fabs(bounded) > st->counts.largest_command) st->counts.largest_command = fabs(bounded);
  }
  st->counts.saturated += report->saturated;
  st->counts.rate_limited += report->rate_limited;
  st->t_held = t_now;
  st->t_last = t_now;
  remember(st, t_now, st->u_held);
  return HINF_STATUS_OK;
}
"""
