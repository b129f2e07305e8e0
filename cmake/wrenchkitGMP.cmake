# GMP with its C++ interface (libgmp-dev) and MPFR (libmpfr-dev: the rigorous interval bounds of support regions,
# exact/sliding/region_sliding.cpp) as one imported target, wrenchkit::gmp_libraries, for the build tree and for
# installed packages alike (wrenchkitConfig.cmake includes this file too).
# Sets wrenchkit_GMP_FOUND. Honours GMP_INCLUDE_DIR, GMP_LIBRARY, GMPXX_LIBRARY, MPFR_INCLUDE_DIR, MPFR_LIBRARY.
find_path(GMP_INCLUDE_DIR gmpxx.h)
find_library(GMP_LIBRARY gmp)
find_library(GMPXX_LIBRARY gmpxx)
find_path(MPFR_INCLUDE_DIR mpfr.h)
find_library(MPFR_LIBRARY mpfr)
if(GMP_INCLUDE_DIR AND GMP_LIBRARY AND GMPXX_LIBRARY AND MPFR_INCLUDE_DIR AND MPFR_LIBRARY)
  set(wrenchkit_GMP_FOUND TRUE)
else()
  set(wrenchkit_GMP_FOUND FALSE)
endif()
if(wrenchkit_GMP_FOUND AND NOT TARGET wrenchkit::gmp_libraries)
  add_library(wrenchkit::gmp_libraries INTERFACE IMPORTED)
  set_target_properties(wrenchkit::gmp_libraries PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${GMP_INCLUDE_DIR};${MPFR_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "${GMPXX_LIBRARY};${MPFR_LIBRARY};${GMP_LIBRARY}")
endif()
