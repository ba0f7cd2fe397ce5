/* A vehicle loop in C: the exported controller (hinf-cpp export-controller) driven at its period
   against the paper's ship simulated in the same program, Figure 2 on a 20 Hz computer
   (scenarios/paper_fig2_sampled.toml): x, y, psi measured every T with noise of standard
   deviation 0.5, the command computed 20 ms later (the controller predicts over the delay) and
   held, the paper's disturbance 0.1 cos(2 pi 0.2 t) on the three forces.

   The ship, paper eqs. (1)-(6) with the parameters of the scenario (docs/mathematics.md):
     du/dt   = m_u v r - d_u u + u1 + w1       dx/dt   = u cos(psi) - v sin(psi)
     dv/dt   = m_v u r - d_v v      + w2       dy/dt   = u sin(psi) + v cos(psi)
     dr/dt   = m_r u v - d_r r + u2 + w3       dpsi/dt = r
   integrated by classical Runge-Kutta steps of 1 ms (the command and the disturbance's phase
   within a step: the disturbance is smooth, the command constant between events).

   Build with the exported folder: cc -std=c99 -O2 -I DIR main.c DIR/hinf_controller.c
   DIR/hinf_controller_tables.c -lm; run: ./loop OUT.csv [SEED]. Writes t, q (6), q_d (6), u (2)
   at every sample. examples/vehicle_loop_c.py does all of it and plots the CSV. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "hinf_controller.h"

#define PI 3.14159265358979323846

static const double m_u = 0.5, m_v = -2.0, m_r = 0.5, d_u = 1.0, d_v = 2.0, d_r = 1.0;
static const double sigma = 0.5;    /* noise per measurement (x, y in m, psi in rad) */
static const double delay = 0.02;   /* s: computation delay */
static const double h = 0.001;      /* s: the plant's integration step */

static void ship(double t, const double *q, const double *u, double *dq) {
  const double w = 0.1 * cos(2.0 * PI * 0.2 * t);
  dq[0] = m_u * q[1] * q[2] - d_u * q[0] + u[0] + w;
  dq[1] = m_v * q[0] * q[2] - d_v * q[1] + w;
  dq[2] = m_r * q[0] * q[1] - d_r * q[2] + u[1] + w;
  dq[3] = q[0] * cos(q[5]) - q[1] * sin(q[5]);
  dq[4] = q[0] * sin(q[5]) + q[1] * cos(q[5]);
  dq[5] = q[2];
}

/* The plant from t to t_end under the command u held. */
static void simulate(double *q, double t, double t_end, const double *u) {
  while (t < t_end - 1e-12) {
    const double dt = t_end - t < h ? t_end - t : h;
    double k1[6], k2[6], k3[6], k4[6], s[6];
    int i;
    ship(t, q, u, k1);
    for (i = 0; i < 6; ++i) s[i] = q[i] + 0.5 * dt * k1[i];
    ship(t + 0.5 * dt, s, u, k2);
    for (i = 0; i < 6; ++i) s[i] = q[i] + 0.5 * dt * k2[i];
    ship(t + 0.5 * dt, s, u, k3);
    for (i = 0; i < 6; ++i) s[i] = q[i] + dt * k3[i];
    ship(t + dt, s, u, k4);
    for (i = 0; i < 6; ++i) q[i] += dt / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
    t += dt;
  }
}

/* Standard normal samples: xorshift64* and Box-Muller (seeded, so a run repeats). */
static unsigned long long rng_state = 20000601ULL;
static double uniform(void) {
  rng_state ^= rng_state >> 12;
  rng_state ^= rng_state << 25;
  rng_state ^= rng_state >> 27;
  return ((rng_state * 2685821657736338717ULL) >> 11) * (1.0 / 9007199254740992.0);
}
static double normal(void) {
  double a = uniform();
  while (a <= 0.0) a = uniform();
  return sqrt(-2.0 * log(a)) * cos(2.0 * PI * uniform());
}

int main(int argc, char **argv) {
  static hinf_controller_state controller; /* the caller owns the controller's memory */
  /* Start 1 m behind and 1 m aside with a 45 degree heading error; the estimate starts on the
     path, at q_d(t0) (the scenario's [desired] q0). */
  double q[6] = {1.0, 0.0, 0.0, -1.0, -1.0, PI / 4.0};
  const double q_hat0[6] = {1.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  double u[HINF_M], y[3], q_d[HINF_N];
  int k, i, refused = 0;
  FILE *csv;
  if (argc < 2) {
    fprintf(stderr, "usage: %s OUT.csv [SEED]\n", argv[0]);
    return 2;
  }
  if (argc > 2) rng_state = strtoull(argv[2], NULL, 10) | 1ULL;
  csv = fopen(argv[1], "w");
  if (csv == NULL) {
    perror(argv[1]);
    return 1;
  }
  hinf_controller_init(&controller);
  if (hinf_controller_reset(&controller, HINF_T0, q_hat0, NULL) != 0) return 1;
  for (i = 0; i < HINF_M; ++i) u[i] = controller.u_held[i];
  fprintf(csv, "t,u_s,v,r,x,y,psi,u_d_s,v_d,r_d,x_d,y_d,psi_d,u1,u2\n");
  for (k = 0; k < HINF_STEPS; ++k) {
    const double t = HINF_T0 + k * HINF_PERIOD;
    hinf_controller_desired_state(t, q_d);
    fprintf(csv, "%.9g", t);
    for (i = 0; i < 6; ++i) fprintf(csv, ",%.9g", q[i]);
    for (i = 0; i < 6; ++i) fprintf(csv, ",%.9g", q_d[i]);
    for (i = 0; i < HINF_M; ++i) fprintf(csv, ",%.9g", u[i]);
    fprintf(csv, "\n");
    /* The sensor at t_k; the answer 20 ms later, held until the next one. */
    for (i = 0; i < 3; ++i) y[i] = q[3 + i] + sigma * normal();
    simulate(q, t, t + delay, u);
    if (hinf_controller_step(&controller, t + delay, y, t, u) != HINF_STATUS_OK) ++refused;
    simulate(q, t + delay, t + HINF_PERIOD, u);
  }
  fclose(csv);
  printf("%d samples, %ld measurements used, %ld saturated, %ld rate limited, %d steps not ok\n", HINF_STEPS,
         controller.counts.used, controller.counts.saturated, controller.counts.rate_limited, refused);
  return refused == 0 ? 0 : 1;
}
