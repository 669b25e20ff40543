// The main() of every lab executable; pba_add_lab() compiles it in with PBA_LAB_NAME set.
#include "app/lab.h"

int main(int argc, char** argv) { return pba::app::runLab(PBA_LAB_NAME, argc, argv); }
