// Lab flags of pba-cloth: --solver NAME sets the scene parameter of that name.
#include "app/runner/scene_registry.h"

PBA_REGISTER_LAB_FLAG("solver", "solver", "cloth solver: explicit, implicit, pbd, xpbd");
