# The installed application finds its data without the source tree: `cmake --install` into a
# scratch prefix lays out bin/, share/octaclay/, the desktop entry and the icon; the installed
# octaclay-cli, run from the scratch folder with a bare environment, lists every built-in brush
# (one per plugins/brushes folder) from share/octaclay/brushes and the materials from
# share/octaclay/materials. A brush and a material removed from the installed copy then vanish
# from its lists, so they cannot have come from the source tree.
# cmake -DBUILD_DIR=<build> -DSOURCE_DIR=<source> -DWORK_DIR=<scratch> -P install_test.cmake
cmake_minimum_required(VERSION 3.25)
include("${CMAKE_CURRENT_LIST_DIR}/brush_lists.cmake")
foreach(var BUILD_DIR SOURCE_DIR WORK_DIR)
  if(NOT ${var})
    message(FATAL_ERROR "install_test: pass -D${var}=…")
  endif()
endforeach()

file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}/home")
set(prefix "${WORK_DIR}/usr")
execute_process(COMMAND "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${prefix}"
                RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cmake --install failed (${rc}): ${err}")
endif()

foreach(path bin/octaclay bin/octaclay-cli share/applications/octaclay.desktop
             share/icons/hicolor/scalable/apps/octaclay.svg share/octaclay/brushes/push/manifest.json
             share/octaclay/materials/brick share/octaclay/environment/studio.png)
  if(NOT EXISTS "${prefix}/${path}")
    message(FATAL_ERROR "not installed: ${path}")
  endif()
endforeach()

# Runs the installed CLI with no OCTACLAY_* variables and a scratch home (no user brushes).
function(run_installed_cli out_var err_var rc_var)
  execute_process(
    COMMAND env -i "PATH=/usr/bin:/bin" "HOME=${WORK_DIR}/home"
            "XDG_DATA_HOME=${WORK_DIR}/home/.local/share" "${prefix}/bin/octaclay-cli" ${ARGN}
    WORKING_DIRECTORY "${WORK_DIR}" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  set(${out_var} "${out}" PARENT_SCOPE)
  set(${err_var} "${err}" PARENT_SCOPE)
  set(${rc_var} "${rc}" PARENT_SCOPE)
endfunction()

# The ids `brushes --json` lists, each checked to come from the installed share/octaclay.
function(installed_brushes ids_var)
  run_installed_cli(out err rc brushes --json)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "octaclay-cli brushes failed (${rc}): ${err}")
  endif()
  listed_brushes("${out}" "${prefix}/share/octaclay/brushes" ids)
  set(${ids_var} "${ids}" PARENT_SCOPE)
endfunction()

built_in_brushes("${SOURCE_DIR}" expected)
installed_brushes(found)
if(NOT found STREQUAL expected)
  message(FATAL_ERROR "the installed octaclay-cli lists [${found}], the built-in brushes are [${expected}]")
endif()
list(LENGTH found n)
message(STATUS "installed octaclay-cli finds all ${n} built-in brushes: ${found}")

# Materials: an unknown one is refused with the list of those found.
run_installed_cli(out err rc new --shape sphere --size 16 -o "${WORK_DIR}/sphere.exr")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "octaclay-cli new failed (${rc}): ${err}")
endif()
set(splat stroke "${WORK_DIR}/sphere.exr" --brush splat --path 0.5,0.5 --param material=velvet
          -o "${WORK_DIR}/never.exr")
run_installed_cli(out err rc ${splat})
foreach(material brick stone wood)
  string(FIND "${err}" "${material}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "the installed octaclay-cli does not find the material ${material}: ${err}")
  endif()
endforeach()

# The installed copy is what they read: remove one brush and one material from it.
file(REMOVE_RECURSE "${prefix}/share/octaclay/brushes/smooth" "${prefix}/share/octaclay/materials/wood")
installed_brushes(found)
list(REMOVE_ITEM expected smooth)
if(NOT found STREQUAL expected)
  message(FATAL_ERROR "with smooth removed from the installed brushes, octaclay-cli lists [${found}]")
endif()
run_installed_cli(out err rc ${splat})
string(FIND "${err}" "wood" wood)
string(FIND "${err}" "brick" brick)
if(NOT wood EQUAL -1 OR brick EQUAL -1)
  message(FATAL_ERROR "with wood removed from the installed materials: ${err}")
endif()
file(REMOVE_RECURSE "${WORK_DIR}")
