# octaclay_add_test(NAME <name> SOURCES <files...> LABELS <labels...> [LIBS <libs...>])
# Builds one QtTest executable and registers it with CTest. Tests find the shared test meshes
# through OCTACLAY_SHARED_DATA (OCTACLAY_REQUIRE_SHARED_DATA: whether a missing one fails) and
# the CLI through OCTACLAY_CLI.
set(OCTACLAY_SHARED_DATA "${PROJECT_SOURCE_DIR}/../shared/data" CACHE PATH
    "Folder holding the shared test meshes (meshes/genus0, meshes/invalid)")
# Off, the acceptance tests skip when a shared mesh is missing; on (the ci preset), they fail.
option(OCTACLAY_REQUIRE_SHARED_DATA "Tests fail instead of skipping without OCTACLAY_SHARED_DATA"
       OFF)

function(octaclay_add_test)
  cmake_parse_arguments(ARG "" "NAME" "SOURCES;LABELS;LIBS" ${ARGN})
  add_executable(${ARG_NAME} ${ARG_SOURCES})
  target_link_libraries(${ARG_NAME} PRIVATE octaclay_core Qt6::Test ${ARG_LIBS})
  octaclay_set_warnings(${ARG_NAME})
  target_compile_definitions(${ARG_NAME} PRIVATE
    OCTACLAY_SHARED_DATA="${OCTACLAY_SHARED_DATA}"
    OCTACLAY_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
    OCTACLAY_REQUIRE_SHARED_DATA=$<BOOL:${OCTACLAY_REQUIRE_SHARED_DATA}>
    OCTACLAY_CLI="$<TARGET_FILE:octaclay-cli>")
  add_test(NAME ${ARG_NAME} COMMAND ${ARG_NAME})
  set_tests_properties(${ARG_NAME} PROPERTIES LABELS "${ARG_LABELS}"
    ENVIRONMENT "QT_QPA_PLATFORM=offscreen")
endfunction()
