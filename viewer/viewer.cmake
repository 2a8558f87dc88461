# The viewer of `cslice view` (docs/viewer.md), included by the top-level CMakeLists.txt when
# CSLICE_VIEWER is ON. Build steps, all in the build directory so that several build
# directories never share a node_modules:
#   1. npm ci from viewer/package-lock.json (three, esbuild, playwright-core, pinned);
#   2. esbuild bundles viewer/src with three.js into one script, viewer/viewer.js;
#   3. viewer/embed.cmake turns template.html and that script into viewer_assets.cpp,
#      compiled into the cslice program.
# Sets CSLICE_VIEWER_ASSETS (the generated source) and CSLICE_VIEWER_NODE_MODULES (for the
# browser test, tests/viewer), and CSLICE_NODE.

set(viewer_source_dir ${CMAKE_CURRENT_LIST_DIR})
set(viewer_build_dir ${CMAKE_BINARY_DIR}/viewer)

find_program(CSLICE_NODE node)
find_program(CSLICE_NPM npm)
if(NOT CSLICE_NODE OR NOT CSLICE_NPM)
  message(FATAL_ERROR
    "cslice: the viewer (cslice view) needs node and npm to build, and they were not found.\n"
    "Run `bash scripts/install-deps.sh` as root to install them, or configure with "
    "-DCSLICE_VIEWER=OFF to build cslice without the viewer.")
endif()
execute_process(COMMAND ${CSLICE_NODE} --version OUTPUT_VARIABLE node_version
  OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE node_result)
string(REGEX REPLACE "^v([0-9]+).*" "\\1" node_major "${node_version}")
if(NOT node_result EQUAL 0 OR node_major LESS 18)
  message(FATAL_ERROR "cslice: the viewer needs node 18 or later; ${CSLICE_NODE} is "
    "'${node_version}'. Run `bash scripts/install-deps.sh`, or configure with -DCSLICE_VIEWER=OFF.")
endif()

file(MAKE_DIRECTORY ${viewer_build_dir})
set(viewer_npm_stamp ${viewer_build_dir}/npm-ci.stamp)
add_custom_command(
  OUTPUT ${viewer_npm_stamp}
  COMMAND ${CMAKE_COMMAND} -E copy_if_different
    ${viewer_source_dir}/package.json ${viewer_source_dir}/package-lock.json ${viewer_build_dir}
  # ci, not install: exactly the lock file's versions, or an error.
  COMMAND ${CSLICE_NPM} ci --no-audit --no-fund --loglevel=error
  COMMAND ${CMAKE_COMMAND} -E touch ${viewer_npm_stamp}
  WORKING_DIRECTORY ${viewer_build_dir}
  DEPENDS ${viewer_source_dir}/package.json ${viewer_source_dir}/package-lock.json
  COMMENT "Installing the viewer's node packages (npm ci)"
  VERBATIM)

file(GLOB viewer_js_sources CONFIGURE_DEPENDS ${viewer_source_dir}/src/*.js)
set(viewer_bundle ${viewer_build_dir}/viewer.js)
add_custom_command(
  OUTPUT ${viewer_bundle}
  # npx runs the esbuild that npm ci installed beside the lock file (--no-install: never
  # fetch another). NODE_PATH lets the sources in viewer/src import 'three' from there.
  COMMAND ${CMAKE_COMMAND} -E env NODE_PATH=${viewer_build_dir}/node_modules
    ${CSLICE_NPM} exec --no -- esbuild ${viewer_source_dir}/src/main.js
    --bundle --minify --format=iife --target=es2020 --charset=ascii --log-level=warning
    --outfile=${viewer_bundle}
  WORKING_DIRECTORY ${viewer_build_dir}
  DEPENDS ${viewer_npm_stamp} ${viewer_js_sources}
  COMMENT "Bundling the viewer with three.js (esbuild)"
  VERBATIM)

set(CSLICE_VIEWER_ASSETS ${viewer_build_dir}/viewer_assets.cpp)
add_custom_command(
  OUTPUT ${CSLICE_VIEWER_ASSETS}
  COMMAND ${CMAKE_COMMAND} -DTEMPLATE=${viewer_source_dir}/template.html
    -DBUNDLE=${viewer_bundle} -DOUTPUT=${CSLICE_VIEWER_ASSETS} -P ${viewer_source_dir}/embed.cmake
  DEPENDS ${viewer_source_dir}/template.html ${viewer_bundle} ${viewer_source_dir}/embed.cmake
  COMMENT "Embedding the viewer page and script in cslice"
  VERBATIM)
set(CSLICE_VIEWER_NODE_MODULES ${viewer_build_dir}/node_modules)
