# The web app's front end (frontend/): npm packages pinned by frontend/package-lock.json
# (installed by scripts/setup.sh with `npm ci`), bundled by esbuild into <build>/web-root,
# which `swarmdesign run-exp` serves. Its browser tests run in Debian's chromium.
find_program(SWARMDESIGN_NODE node)
set(frontend_dir ${PROJECT_SOURCE_DIR}/frontend)
if(NOT SWARMDESIGN_NODE OR NOT EXISTS ${frontend_dir}/node_modules/esbuild)
  message(FATAL_ERROR "The web app's front end needs Node.js and its npm packages: run scripts/setup.sh "
                      "(or: cd frontend && npm ci)")
endif()
file(GLOB_RECURSE frontend_sources CONFIGURE_DEPENDS ${frontend_dir}/src/* ${frontend_dir}/index.html
     ${frontend_dir}/build.mjs ${frontend_dir}/favicon.mjs ${frontend_dir}/package-lock.json)
set(web_root ${PROJECT_BINARY_DIR}/web-root)
add_custom_command(OUTPUT ${web_root}/index.html
                   COMMAND ${SWARMDESIGN_NODE} build.mjs --outdir ${web_root}
                   WORKING_DIRECTORY ${frontend_dir}
                   DEPENDS ${frontend_sources}
                   COMMENT "Bundling the web app's front end into ${web_root}")
add_custom_target(frontend ALL DEPENDS ${web_root}/index.html)
add_dependencies(swarmdesign frontend)
