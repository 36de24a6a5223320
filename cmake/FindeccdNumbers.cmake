# FindeccdNumbers: the number libraries eccd links (Debian: libgmp-dev,
# libmpfr-dev, libmpfi-dev, libflint-dev), as imported targets eccd::gmp, eccd::gmpxx,
# eccd::mpfr, eccd::mpfi, eccd::flint (exact/flint_poly.cpp only). Used by eccd's own build and by its installed
# package (eccdConfig.cmake), so a consumer needs nothing but find_package(eccd).
include(FindPackageHandleStandardArgs)
find_path(ECCD_GMPXX_INCLUDE gmpxx.h)
find_library(ECCD_GMP_LIB gmp)
find_library(ECCD_GMPXX_LIB gmpxx)
find_library(ECCD_MPFR_LIB mpfr)
find_library(ECCD_MPFI_LIB mpfi)
find_library(ECCD_FLINT_LIB flint)
find_package_handle_standard_args(eccdNumbers REQUIRED_VARS
  ECCD_GMPXX_INCLUDE ECCD_GMP_LIB ECCD_GMPXX_LIB ECCD_MPFR_LIB ECCD_MPFI_LIB ECCD_FLINT_LIB)
foreach(lib gmp gmpxx mpfr mpfi flint)
  string(TOUPPER ${lib} LIB)
  if(eccdNumbers_FOUND AND NOT TARGET eccd::${lib})
    add_library(eccd::${lib} UNKNOWN IMPORTED)
    set_target_properties(eccd::${lib} PROPERTIES IMPORTED_LOCATION "${ECCD_${LIB}_LIB}"
                          INTERFACE_INCLUDE_DIRECTORIES "${ECCD_GMPXX_INCLUDE}")
  endif()
endforeach()
