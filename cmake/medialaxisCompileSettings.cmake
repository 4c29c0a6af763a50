# Compile settings shared by the main build (CMakeLists.txt) and the ParaView plugin build
# (ParaView/CMakeLists.txt), which compile the same modules.
set(CMAKE_CXX_STANDARD 17)
set(CMAKE_CXX_STANDARD_REQUIRED ON)
# Only classes marked with a module's export macro leave the shared libraries; the
# private engines of Filters/Core stay inside each library that links them.
set(CMAKE_CXX_VISIBILITY_PRESET hidden)
set(CMAKE_VISIBILITY_INLINES_HIDDEN ON)
set(CMAKE_POSITION_INDEPENDENT_CODE ON)
if (NOT CMAKE_BUILD_TYPE AND NOT CMAKE_CONFIGURATION_TYPES)
  set(CMAKE_BUILD_TYPE Release CACHE STRING "Build type" FORCE)
endif ()
# Never fuse a * b + c into one rounding (GCC fuses by default wherever the target
# has FMA: -march=native, x86-64-v3, every aarch64). The watertight ray test needs a
# shared edge's two edge functions to be exact negatives, and the distance bounds
# and the sampler's "same bits" promise need every CPU to round alike.
# TestMedialNoContraction fails if this goes.
if (CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
  add_compile_options(-ffp-contract=off)
endif ()
