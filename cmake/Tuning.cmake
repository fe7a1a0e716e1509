# Code-generation choices for our own targets (through suspend_options), not semantics.
# GCC expands fixed-size memset/memcpy of small structs (e.g. zeroing a 168-byte ResistanceScalars) as
# `rep stosq` / `rep movsq`, whose start-up costs tens of cycles on the AMD cores this project runs on: in the
# sub-grid assembly of a coupled FCM step they took half the time of SubgridLubrication::scalars (perf). Up to
# 512 bytes they become unrolled vector moves; larger ones stay library calls. Measured with bench_coupling:
# assembly 3.1 -> 2.0 bare FFT solves per step (docs/coupling.md section 6).
include(CheckCXXCompilerFlag)
if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_SYSTEM_PROCESSOR MATCHES "x86_64|AMD64")
  set(_suspend_stringops "-mmemset-strategy=unrolled_loop:512:noalign,libcall:-1:noalign"
                         "-mmemcpy-strategy=unrolled_loop:512:noalign,libcall:-1:noalign")
  check_cxx_compiler_flag("${_suspend_stringops}" SUSPEND_HAS_STRINGOP_STRATEGY)
  if(SUSPEND_HAS_STRINGOP_STRATEGY)
    target_compile_options(suspend_options INTERFACE ${_suspend_stringops})
  endif()
endif()
