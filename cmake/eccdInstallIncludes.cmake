# Run by `cmake --install` (install(CODE) in CMakeLists.txt), after the headers are copied.
# eccd's sources include each other as "kernel/x.hpp", "api/y.hpp" (the source root is on their
# include path). In the installed copies under <prefix>/include/eccd/ those includes become
# "eccd/kernel/x.hpp", "eccd/api/y.hpp": a consumer puts only <prefix>/include on its include
# path, and a folder of its own named kernel/, io/, api/, ... cannot be taken for eccd's.
# In: ECCD_INCLUDEDIR (CMAKE_INSTALL_INCLUDEDIR), ECCD_LAYERS (the installed layer folders);
# CMAKE_INSTALL_PREFIX and DESTDIR as the install sets them. Rewriting twice changes nothing.
if(IS_ABSOLUTE "${ECCD_INCLUDEDIR}")
  set(dir "$ENV{DESTDIR}${ECCD_INCLUDEDIR}/eccd")
else()
  set(dir "$ENV{DESTDIR}${CMAKE_INSTALL_PREFIX}/${ECCD_INCLUDEDIR}/eccd")
endif()
string(REPLACE ";" "|" layers "${ECCD_LAYERS}")
file(GLOB_RECURSE headers "${dir}/*.hpp")
set(rewritten 0)
foreach(h IN LISTS headers)
  file(READ "${h}" text)
  string(REGEX REPLACE "(#[ \t]*include[ \t]*\")(${layers})/" "\\1eccd/\\2/" new_text "${text}")
  if(NOT new_text STREQUAL text)
    file(WRITE "${h}" "${new_text}")
    math(EXPR rewritten "${rewritten} + 1")
  endif()
endforeach()
list(LENGTH headers total)
message(STATUS "eccd: includes of ${rewritten} of ${total} installed headers rewritten to \"eccd/<layer>/...\" in ${dir}")
