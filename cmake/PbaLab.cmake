# pba_add_lab(<name> SOURCES <files...>)
# Builds executable pba-<name> from the lab's scene files plus the shared lab main of pba::app.
# Scenes register themselves (PBA_REGISTER_SCENE), so their objects are compiled straight into the
# executable, never into a static library where the linker could drop them.
function(pba_add_lab name)
  cmake_parse_arguments(LAB "" "" "SOURCES" ${ARGN})
  if(NOT LAB_SOURCES)
    message(FATAL_ERROR "pba_add_lab(${name}): SOURCES is empty")
  endif()
  set(target pba-${name})
  add_executable(${target} ${LAB_SOURCES} ${PBA_LAB_MAIN_SOURCE})
  target_link_libraries(${target} PRIVATE pba::app)
  target_compile_definitions(${target} PRIVATE PBA_LAB_NAME="${name}")
  pba_target_warnings(${target})
  # One unity batch per lab: its scenes register in the order of SOURCES (the first is the default scene),
  # which within one translation unit the language defines; across units the order is the linker's.
  set_target_properties(${target} PROPERTIES RUNTIME_OUTPUT_DIRECTORY "${CMAKE_BINARY_DIR}/bin" UNITY_BUILD_BATCH_SIZE 0)
  set_property(GLOBAL APPEND PROPERTY PBA_LABS ${name})
endfunction()
