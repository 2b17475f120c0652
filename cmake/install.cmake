# `cmake --install build [--prefix P]` lays out a working SwarmDesign, and `cpack` (in build/)
# packs the same tree as a Debian package:
#   bin/swarmdesign
#   share/swarmdesign/web-root/        the web app's pages (run-exp finds them beside bin/)
#   share/swarmdesign/missions/        the mission catalogue as files, to copy and edit
#   lib/python3.X/dist-packages/swarmdesign/   the Python module (on Debian's python3 path
#                                      under /usr and /usr/local alike)
#   share/doc/swarmdesign/             README and the Demiurge licence
install(TARGETS swarmdesign RUNTIME DESTINATION bin)
install(DIRECTORY ${PROJECT_BINARY_DIR}/web-root/ DESTINATION share/swarmdesign/web-root)
install(DIRECTORY missions/ DESTINATION share/swarmdesign/missions)
install(FILES README.md DESTINATION share/doc/swarmdesign)
# Demiurge's networks and grey tables are compiled into the binary; its MIT licence asks for
# its notice with every copy.
install(FILES data/arlequin-demiurge/LICENSE DESTINATION share/doc/swarmdesign RENAME LICENSE.demiurge)

if(TARGET swarmdesign_python)
  if(NOT DEFINED PYTHON_VERSION_MAJOR OR NOT DEFINED PYTHON_VERSION_MINOR)
    execute_process(COMMAND ${PYTHON_EXECUTABLE} -c "import sys; print(*sys.version_info[:2], sep=';')"
                    OUTPUT_VARIABLE python_version OUTPUT_STRIP_TRAILING_WHITESPACE)
    list(GET python_version 0 PYTHON_VERSION_MAJOR)
    list(GET python_version 1 PYTHON_VERSION_MINOR)
  endif()
  set(SWARMDESIGN_PYTHON_INSTALL_DIR "lib/python${PYTHON_VERSION_MAJOR}.${PYTHON_VERSION_MINOR}/dist-packages"
      CACHE STRING "Where the Python package swarmdesign is installed, relative to the prefix")
  install(TARGETS swarmdesign_python LIBRARY DESTINATION ${SWARMDESIGN_PYTHON_INSTALL_DIR}/swarmdesign)
  file(GLOB python_package_files CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/python/swarmdesign/*.py
       ${PROJECT_SOURCE_DIR}/python/swarmdesign/*.pyi ${PROJECT_SOURCE_DIR}/python/swarmdesign/py.typed)
  install(FILES ${python_package_files} DESTINATION ${SWARMDESIGN_PYTHON_INSTALL_DIR}/swarmdesign)
endif()

# The Debian package: the same tree under /usr. Library dependencies come from
# dpkg-shlibdeps (dpkg-dev, part of build-essential); the Python module needs numpy and the
# python3 it was built for.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME swarmdesign)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "Automatic modular design of robot swarms (AutoMoDe)")
set(CPACK_PACKAGE_CONTACT "SwarmDesign developers")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
if(TARGET swarmdesign_python)
  math(EXPR python_next_minor "${PYTHON_VERSION_MINOR} + 1")
  set(CPACK_DEBIAN_PACKAGE_DEPENDS
      "python3 (>= ${PYTHON_VERSION_MAJOR}.${PYTHON_VERSION_MINOR}), python3 (<< ${PYTHON_VERSION_MAJOR}.${python_next_minor}), python3-numpy")
endif()
include(CPack)
