// Lab flags of pba-animation (--skeleton is registered with the mocap scene).
#include "app/scene_registry.h"

PBA_REGISTER_LAB_FLAG("pose-json", "pose_json",
                      "write the world position of every joint, by name, to FILE when the run ends");
