// Lab flags of pba-particles: --integrator NAME and --particles N set the scene parameters of those names.
#include "app/runner/scene_registry.h"

PBA_REGISTER_LAB_FLAG("integrator", "integrator",
                      "time integrator: euler, symplectic-euler, midpoint, rk4, verlet, velocity-verlet, "
                      "implicit-euler, adaptive");
PBA_REGISTER_LAB_FLAG("particles", "particles",
                      "number of particles (fountain pool size, up to 1000000; selects fountain without --scene)",
                      "fountain");
