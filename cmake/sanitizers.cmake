# VLO_SANITIZE: ASan + UBSan on every target (make test-sanitize, build-asan/).
# VLO_FUZZ: the same plus libFuzzer's coverage instrumentation, for the harnesses in fuzz/ (clang).
if(VLO_SANITIZE OR VLO_FUZZ)
  set(_vlo_san -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
  if(VLO_FUZZ)
    if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
      message(FATAL_ERROR "VLO_FUZZ needs clang (libFuzzer): configure with -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_C_COMPILER=clang")
    endif()
    list(APPEND _vlo_san -fsanitize=fuzzer-no-link)
  endif()
  add_compile_options(${_vlo_san})
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    # Under -fsanitize=address GCC 12 warns "may be used uninitialized" inside libstdc++'s <regex>: a false
    # positive in the standard library, not our code. The normal build keeps the warning.
    add_compile_options(-Wno-maybe-uninitialized)
  endif()
  add_link_options(-fsanitize=address,undefined)
  # One name for "built with ASan", whichever the compiler (each spells its own differently): the corrupt-input guard
  # leaves operator new to ASan, and the tests set no address-space limit under it.
  add_compile_definitions(VLO_ADDRESS_SANITIZER)
endif()
if(VLO_SANITIZE)
  # List the tests when ctest runs, under the sanitizer options of `make test-sanitize`, not at build time.
  set(CMAKE_GTEST_DISCOVER_TESTS_DISCOVERY_MODE PRE_TEST)
endif()
