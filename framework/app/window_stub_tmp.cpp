#include <iostream>
#include "app/lab.h"
namespace pba::app {
int runWindow(const std::string& lab, const LabOptions&, SceneRunner&) { std::cerr << "pba-" << lab << ": window mode not built yet\n"; return 1; }
}
