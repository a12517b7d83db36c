include(GoogleTest)
# vlo_add_module(<name> DEPS <targets...>)
# Builds modules/<name>/src/*.cpp into library vlo_<name> (alias vlo::<name>) with public headers in
# include/, and every modules/<name>/tests/*.cpp into one gtest executable registered with ctest.
set(VLO_WARNINGS -Wall -Wextra)

function(vlo_add_module name)
  cmake_parse_arguments(ARG "" "" "DEPS;TEST_DEPS" ${ARGN})
  file(GLOB srcs CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/src/*.cpp)
  add_library(vlo_${name} STATIC ${srcs})
  add_library(vlo::${name} ALIAS vlo_${name})
  target_include_directories(vlo_${name} PUBLIC ${CMAKE_CURRENT_SOURCE_DIR}/include)
  target_link_libraries(vlo_${name} PUBLIC ${ARG_DEPS})
  target_compile_options(vlo_${name} PRIVATE ${VLO_WARNINGS})

  file(GLOB tests CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/tests/*.cpp)
  if(VLO_BUILD_TESTS AND tests)
    add_executable(test_${name} ${tests})
    target_link_libraries(test_${name} PRIVATE vlo_${name} ${ARG_TEST_DEPS} GTest::gtest_main)
    target_compile_options(test_${name} PRIVATE ${VLO_WARNINGS})
    target_include_directories(test_${name} PRIVATE ${CMAKE_SOURCE_DIR}/tests/support)
    target_compile_definitions(test_${name} PRIVATE
      VLO_SHARED_DATA="${CMAKE_SOURCE_DIR}/../shared/data"
      VLO_BIN_DIR="${CMAKE_BINARY_DIR}/bin"
      VLO_SOURCE_DIR="${CMAKE_SOURCE_DIR}")
    # Scratch folders under the build (gtest's TempDir): two builds testing at once do not share /tmp paths.
    file(MAKE_DIRECTORY ${CMAKE_BINARY_DIR}/tmp)
    gtest_discover_tests(test_${name} WORKING_DIRECTORY ${CMAKE_BINARY_DIR}
      DISCOVERY_TIMEOUT 60 PROPERTIES TIMEOUT 600 ENVIRONMENT "TEST_TMPDIR=${CMAKE_BINARY_DIR}/tmp/")
  endif()
endfunction()

# vlo_add_app(<name> DEPS <targets...>): apps/<name>.cpp -> build/bin/<name>
function(vlo_add_app name)
  cmake_parse_arguments(ARG "" "" "DEPS" ${ARGN})
  add_executable(${name} ${CMAKE_CURRENT_SOURCE_DIR}/${name}.cpp)
  target_link_libraries(${name} PRIVATE ${ARG_DEPS})
  target_compile_options(${name} PRIVATE ${VLO_WARNINGS})
endfunction()

# vlo_register_module(<name> SOURCES <files...> DEPS <targets...>)
# An implementation of a module family (modules/kernel), kept beside its estimator, that registers
# itself with VLO_REGISTER_MODULE. It is built as an OBJECT library vlo_module_<name>: its objects
# are linked whole into each program that lists it, so the linker cannot drop the registration as it
# would from a static archive that nothing references. Every such library is appended to the global
# property VLO_REGISTERED_MODULES, which vlo-run links.
function(vlo_register_module name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS" ${ARGN})
  add_library(vlo_module_${name} OBJECT ${ARG_SOURCES})
  target_link_libraries(vlo_module_${name} PUBLIC vlo::kernel ${ARG_DEPS})
  target_compile_options(vlo_module_${name} PRIVATE ${VLO_WARNINGS})
  set_property(GLOBAL APPEND PROPERTY VLO_REGISTERED_MODULES vlo_module_${name})
endfunction()
