# `cmake --install build/<preset> --prefix DIR` lays out a self-contained folder:
#   DIR/bin/pba-<lab>[.exe]                 every lab
#   DIR/lib/ (or bin/ on Windows)           the physics library when it is shared
#   DIR/share/pba-labs/resources/           shaders, the UI font, models, scenes, the exercise catalog
# A lab finds the resources there relative to its own path (app/runner/resource_dir.h), so the folder can be
# moved, zipped or copied to another machine of the same system.
get_property(pba_labs GLOBAL PROPERTY PBA_LABS)
foreach(lab ${pba_labs})
  install(TARGETS pba-${lab} RUNTIME DESTINATION bin)
endforeach()
if(PBA_PHYSICS_SHARED)
  install(TARGETS pba_physics LIBRARY DESTINATION lib RUNTIME DESTINATION bin)
endif()
install(DIRECTORY "${PBA_RESOURCE_DIR}/" DESTINATION share/pba-labs/resources)
