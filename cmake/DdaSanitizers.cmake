# Sanitizer and fuzzing flags (docs/reliability.md, "Fuzzing", "Sanitizers").
#
# Set for every target alike, before any is defined: a library built
# without AddressSanitizer that hands memory to one built with it hides the
# very overflows the build is for. scripts/sanitize.sh and scripts/fuzz.sh
# configure one shared folder (build-sanitize) with both options on, so the
# unit tests and the fuzz targets are compiled once.
if(DDA_FUZZ)
  set(DDA_SANITIZE ON)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "DDA_FUZZ needs clang (libFuzzer): configure with -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_C_COMPILER=clang")
  endif()
endif()

if(DDA_SANITIZE)
  # vptr is off: the dynamic-type check needs RTTI of every class it sees,
  # and CGAL's and Boost's headers give false reports with it. -O1 keeps
  # the run time of the tests bearable with stack traces that still make
  # sense; no -Werror anywhere, as CGAL's and Boost's headers warn here.
  set(DDA_SANITIZER_FLAGS -fsanitize=address,undefined -fno-sanitize=vptr
                          -fno-sanitize-recover=undefined -fno-omit-frame-pointer -O1 -g)
  add_compile_options(${DDA_SANITIZER_FLAGS})
  add_link_options(-fsanitize=address,undefined)
endif()

if(DDA_FUZZ)
  # Coverage instrumentation for libFuzzer in every library; only the fuzz
  # targets link libFuzzer's main (fuzz/CMakeLists.txt).
  add_compile_options(-fsanitize=fuzzer-no-link)
endif()
