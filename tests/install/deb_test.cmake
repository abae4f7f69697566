# The .deb installs into a scratch root and runs from there: CPack's DEB generator (as
# scripts/package runs it) packs this build, `dpkg-deb -x` unpacks it into a scratch root, and
# that root's octaclay-cli, with a bare environment, lists every built-in brush from the root's
# usr/share/octaclay/brushes. The package declares the run-time pieces no linker sees (Qt's
# platform and SVG plugins, Mesa's drivers) and the libraries dpkg-shlibdeps found.
# cmake -DBUILD_DIR=<build> -DSOURCE_DIR=<source> -DWORK_DIR=<scratch> -P deb_test.cmake
cmake_minimum_required(VERSION 3.25)
include("${CMAKE_CURRENT_LIST_DIR}/brush_lists.cmake")
foreach(var BUILD_DIR SOURCE_DIR WORK_DIR)
  if(NOT ${var})
    message(FATAL_ERROR "deb_test: pass -D${var}=…")
  endif()
endforeach()

file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}/home" "${WORK_DIR}/root")
execute_process(COMMAND cpack -G DEB --config "${BUILD_DIR}/CPackConfig.cmake" -B "${WORK_DIR}/pack"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
file(GLOB debs "${WORK_DIR}/pack/octaclay_*.deb")
list(LENGTH debs count)
if(NOT rc EQUAL 0 OR NOT count EQUAL 1)
  message(FATAL_ERROR "cpack -G DEB failed (${rc}, ${count} packages): ${out}${err}")
endif()
execute_process(COMMAND dpkg-deb -f "${debs}" Depends OUTPUT_VARIABLE depends RESULT_VARIABLE rc)
foreach(package qt6-qpa-plugins libqt6svg6 libgl1-mesa-dri libqt6widgets6 libvtk9.1 libopenexr)
  string(FIND "${depends}" "${package}" at)
  if(NOT rc EQUAL 0 OR at EQUAL -1)
    message(FATAL_ERROR "the package does not depend on ${package}: ${depends}")
  endif()
endforeach()
execute_process(COMMAND dpkg-deb -x "${debs}" "${WORK_DIR}/root" RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "dpkg-deb -x failed (${rc}): ${err}")
endif()
set(usr "${WORK_DIR}/root/usr")
foreach(path bin/octaclay bin/octaclay-cli share/applications/octaclay.desktop
             share/icons/hicolor/scalable/apps/octaclay.svg share/octaclay/matcaps/clay.png)
  if(NOT EXISTS "${usr}/${path}")
    message(FATAL_ERROR "not in the package: usr/${path}")
  endif()
endforeach()

execute_process(
  COMMAND env -i "PATH=/usr/bin:/bin" "HOME=${WORK_DIR}/home"
          "XDG_DATA_HOME=${WORK_DIR}/home/.local/share" "${usr}/bin/octaclay-cli" brushes --json
  WORKING_DIRECTORY "${WORK_DIR}" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the unpacked octaclay-cli brushes failed (${rc}): ${err}")
endif()
listed_brushes("${out}" "${usr}/share/octaclay/brushes" found)
built_in_brushes("${SOURCE_DIR}" expected)
list(LENGTH found n)
if(NOT found STREQUAL expected)
  message(FATAL_ERROR "the unpacked octaclay-cli lists [${found}], the built-in brushes are [${expected}]")
endif()
message(STATUS "the .deb's octaclay-cli finds all ${n} built-in brushes")
file(REMOVE_RECURSE "${WORK_DIR}")
