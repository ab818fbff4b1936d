# Included by the top-level CMakeLists.txt before any target when
# EPVIZ_BUILD_FUZZ is on: every library of ours is built with libFuzzer's
# coverage instrumentation and with ASan + UBSan, so that a fuzz target
# explores (and checks) the code behind it, not only its own file.
if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
  message(FATAL_ERROR "EPVIZ_BUILD_FUZZ needs clang (libFuzzer): configure a separate build "
                      "directory with CC=clang CXX=clang++, as scripts/fuzz.sh does")
endif()
add_compile_options(-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined
                    -fno-omit-frame-pointer -g)
add_link_options(-fsanitize=address,undefined)
