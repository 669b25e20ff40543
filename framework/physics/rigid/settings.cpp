#include "physics/rigid/settings.h"

namespace pba::rigid {

std::vector<std::string> positionCorrectionNames() { return {"soft", "baumgarte", "none"}; }
std::vector<std::string> frictionModelNames() { return {"cone", "pyramid"}; }
std::vector<std::string> gyroscopicModeNames() { return {"off", "implicit", "midpoint"}; }

}  // namespace pba::rigid
