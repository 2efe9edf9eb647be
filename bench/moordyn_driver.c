// The MoorDyn side of bench/moordyn_compare.sh (docs/benchmarks.md, "Against MoorDyn"); built by
// that script against a MoorDyn v2 install, not by the project's CMake build.
//
//   moordyn_driver INPUT STEPS_PER_OUTPUT DURATION SPEED OUT.csv
//
// INPUT is a MoorDyn v2 input file whose point 1 is the Coupled towing point and point 2 the
// free sphere. The towing point starts where the input file puts it, at rest for MoorDyn's
// initial condition, and moves along +x at SPEED [m/s] from t = 0 (the impulsive start).
// MoorDyn_Step is called once per dtM, with dtM = 0.2 s / STEPS_PER_OUTPUT (the input file's
// dtM must be that value), so every time step is dtM exactly and rows fall on t = k 0.2 s.
// OUT.csv: `t,x,y,z,tension` every 0.2 s: the sphere's position relative to the towing point
// in towsim's world frame (NED: MoorDyn's z is up, so y and z change sign) [m] and the
// magnitude of the force on the towing point [N].
//
// Exit 0 done, 2 bad arguments, 3 MoorDyn failed (its message on stderr) or the state left the
// finite numbers (then OUT.csv holds every row written before).
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include <moordyn/MoorDyn2.h>

static const double kOutputInterval = 0.2;  // [s], the rows of OUT.csv

static int Fail(MoorDyn system, FILE* out, const char* what, double t) {
  fprintf(stderr, "moordyn_driver: %s at t = %.6g s\n", what, t);
  if (out) fclose(out);
  if (system) MoorDyn_Close(system);
  return 3;
}

int main(int argc, char** argv) {
  if (argc != 6) {
    fprintf(stderr, "usage: moordyn_driver INPUT STEPS_PER_OUTPUT DURATION SPEED OUT.csv\n");
    return 2;
  }
  const long steps_per_output = strtol(argv[2], NULL, 10);
  const double duration = strtod(argv[3], NULL);
  const double speed = strtod(argv[4], NULL);
  if (steps_per_output < 1 || !(duration > 0.0) || !isfinite(speed)) {
    fprintf(stderr,
            "moordyn_driver: STEPS_PER_OUTPUT = %s, DURATION = %s, SPEED = %s: need an integer "
            ">= 1, a duration > 0 and a finite speed\n",
            argv[2], argv[3], argv[4]);
    return 2;
  }
  const double dt = kOutputInterval / (double)steps_per_output;
  const long outputs = lround(duration / kOutputInterval);

  MoorDyn system = MoorDyn_Create(argv[1]);
  if (!system) return Fail(NULL, NULL, "MoorDyn_Create failed", 0.0);
  unsigned int n_dof = 0;
  MoorDyn_NCoupledDOF(system, &n_dof);
  if (n_dof != 3) return Fail(system, NULL, "the input needs exactly one Coupled point", 0.0);
  MoorDynPoint tow = MoorDyn_GetPoint(system, 1);
  MoorDynPoint sphere = MoorDyn_GetPoint(system, 2);
  if (!tow || !sphere) return Fail(system, NULL, "points 1 and 2 are needed", 0.0);

  double x0[3];
  MoorDyn_GetPointPos(tow, x0);
  double x[3] = {x0[0], x0[1], x0[2]};
  double xd[3] = {0.0, 0.0, 0.0};
  double f[3] = {0.0, 0.0, 0.0};
  if (MoorDyn_Init(system, x, xd) != MOORDYN_SUCCESS)
    return Fail(system, NULL, "MoorDyn_Init failed", 0.0);
  xd[0] = speed;

  FILE* out = fopen(argv[5], "w");
  if (!out) {
    perror(argv[5]);
    MoorDyn_Close(system);
    return 2;
  }
  fprintf(out, "t,x,y,z,tension\n");
  double t = 0.0;
  for (long k = 0; k <= outputs; ++k) {
    if (k > 0) {
      for (long s = 1; s <= steps_per_output; ++s) {
        // MoorDyn takes the coupled point's position at the start of the step and moves it
        // on with the velocity over the step (Point::updateFairlead: r = r_ves + rd_ves t)
        const double t_start =
            ((double)(k - 1) + (double)(s - 1) / (double)steps_per_output) * kOutputInterval;
        x[0] = x0[0] + speed * t_start;
        double step = dt;
        if (MoorDyn_Step(system, x, xd, f, &t, &step) != MOORDYN_SUCCESS)
          return Fail(system, out, "MoorDyn_Step failed", t);
      }
    } else {
      MoorDyn_GetPointForce(tow, f);
    }
    double p[3];
    MoorDyn_GetPointPos(sphere, p);
    x[0] = x0[0] + speed * (double)k * kOutputInterval;  // the towing point at this row's t
    const double tension = sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
    const double r[3] = {p[0] - x[0], -(p[1] - x[1]), -(p[2] - x[2])};
    if (!isfinite(r[0]) || !isfinite(r[1]) || !isfinite(r[2]) || !isfinite(tension))
      return Fail(system, out, "non-finite state", t);
    fprintf(out, "%.4f,%.9g,%.9g,%.9g,%.9g\n", (double)k * kOutputInterval, r[0], r[1], r[2],
            tension);
  }
  if (fclose(out) != 0) {
    perror(argv[5]);
    MoorDyn_Close(system);
    return 3;
  }
  MoorDyn_Close(system);
  return 0;
}
