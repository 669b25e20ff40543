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
  if(EMSCRIPTEN)
    pba_web_page(${target})
  endif()
endfunction()

# pba_web_page(<target>): in the browser build, the lab is a page, bin/<target>.html with its .js, .wasm
# and .data (the resources folder, mounted at /resources). The page's URL query becomes the command line
# (cmake/web/query.js); the loop waits for the browser's animation frames through ASYNCIFY
# (graphics/window.cpp). Debian's Emscripten cannot minify HTML (-sMINIFY_HTML=0).
function(pba_web_page target)
  set(web "${CMAKE_SOURCE_DIR}/cmake/web")
  set_target_properties(${target} PROPERTIES SUFFIX ".html")
  target_link_options(${target} PRIVATE -fexceptions -sASYNCIFY "-sASYNCIFY_IMPORTS=['waitForAnimationFrame']" -sASYNCIFY_STACK_SIZE=131072 -sALLOW_MEMORY_GROWTH=1
    -sINITIAL_MEMORY=67108864 -sMINIFY_HTML=0 -sEXPORTED_RUNTIME_METHODS=ccall,FS
    "--preload-file=${PBA_RESOURCE_DIR}@/resources" "--exclude-file=*/licenses/*"
    "--shell-file=${web}/shell.html" "--pre-js=${web}/query.js")
  set_property(TARGET ${target} APPEND PROPERTY LINK_DEPENDS "${web}/shell.html" "${web}/query.js")
endfunction()
