# The CTest test package_consumer (cmake -P): eccd used as a consumer uses it.
#  1. cmake --install the build tree into WORK_DIR/prefix; check the headers
#     (include/eccd/eccd.hpp), the program, the package files are there, that
#     CGAL's definitions did not leak into the exported targets, that the
#     package exports <prefix>/include only and that every installed header
#     includes eccd's others as "eccd/<layer>/...";
#  2. configure, build and run tests/package/consumer/ with find_package(eccd),
#     with the consumer's own kernel/answer.hpp and api/solve.hpp first on its
#     include path (eccd's names, other contents);
#  3. the same with add_subdirectory(eccd source tree), BUILD_TESTING off.
# The consumer solves cases/paper002/example.json exactly and exits 0 only if
# its answer agrees with the stored one. Arguments (-D): ECCD_SOURCE_DIR,
# ECCD_BINARY_DIR, WORK_DIR, CXX_COMPILER, CXX_LAUNCHER (may be empty), BUILD_TYPE,
# ECCD_WERROR (as the build tree has it, so that the subproject's compilations are ccache hits).
# Those hits need ccache's default base_dir (none): with CCACHE_BASEDIR set, ccache keys a compilation by
# paths relative to its working directory, which differs here from the build tree's, and step 3 compiles
# eccd's libraries again (about 200 s on two cores instead of 3 s).
cmake_minimum_required(VERSION 3.18)
foreach(v ECCD_SOURCE_DIR ECCD_BINARY_DIR WORK_DIR CXX_COMPILER)
  if(NOT ${v})
    message(FATAL_ERROR "consumer_test.cmake: -D${v}=... is required")
  endif()
endforeach()
if(NOT BUILD_TYPE)
  set(BUILD_TYPE Release)
endif()
if(NOT ECCD_WERROR)
  set(ECCD_WERROR OFF)
endif()
set(prefix ${WORK_DIR}/prefix)
set(scene ${ECCD_SOURCE_DIR}/cases/paper002/example.json)
set(common -DCMAKE_BUILD_TYPE=${BUILD_TYPE} -DCMAKE_CXX_COMPILER=${CXX_COMPILER})
if(CXX_LAUNCHER)
  list(APPEND common -DCMAKE_CXX_COMPILER_LAUNCHER=${CXX_LAUNCHER})
endif()

function(step what)
  string(TIMESTAMP t0 "%s")
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  string(TIMESTAMP t1 "%s")
  math(EXPR dt "${t1} - ${t0}")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${what}: failed (${rc})\n${out}\n${err}")
  endif()
  message(STATUS "${what}: ok (${dt} s)")
  set(step_output "${out}" PARENT_SCOPE)
endfunction()

# run_consumer(how build_dir [regex]): runs the consumer; its output must say it agrees (and match regex).
function(run_consumer how build_dir)
  step("${how}: run the consumer on cases/paper002/example.json" ${build_dir}/app ${scene})
  string(STRIP "${step_output}" lines)
  string(REPLACE "\n" ";" lines "${lines}")
  foreach(line IN LISTS lines)
    message(STATUS "  ${line}")
  endforeach()
  if(NOT step_output MATCHES "agrees with the stored answer")
    message(FATAL_ERROR "${how}: the consumer did not report agreement:\n${step_output}")
  endif()
  if(ARGC GREATER 2 AND NOT step_output MATCHES "${ARGV2}")
    message(FATAL_ERROR "${how}: the consumer's output does not say \"${ARGV2}\":\n${step_output}")
  endif()
endfunction()

file(REMOVE_RECURSE ${WORK_DIR})

# 1. Install.
step("install into ${prefix}" ${CMAKE_COMMAND} --install ${ECCD_BINARY_DIR} --prefix ${prefix})
foreach(f include/eccd/eccd.hpp include/eccd/api/solve.hpp include/eccd/kernel/answer.hpp bin/eccd
          lib/cmake/eccd/eccdConfig.cmake lib/cmake/eccd/eccdConfigVersion.cmake lib/cmake/eccd/eccdTargets.cmake)
  if(NOT EXISTS ${prefix}/${f})
    message(FATAL_ERROR "install: ${prefix}/${f} is missing")
  endif()
endforeach()
file(GLOB targets_files ${prefix}/lib/cmake/eccd/eccdTargets*.cmake)
foreach(f ${targets_files})
  file(READ ${f} text)
  if(text MATCHES "CGAL")
    message(FATAL_ERROR "install: ${f} mentions CGAL: its definitions must stay private to eccd_exact")
  endif()
endforeach()
file(READ ${prefix}/lib/cmake/eccd/eccdTargets.cmake text)
if(text MATCHES "INTERFACE_INCLUDE_DIRECTORIES \"[^\"]*include/eccd")
  message(FATAL_ERROR "install: eccdTargets.cmake exports include/eccd: a consumer must need only <prefix>/include")
endif()
file(GLOB_RECURSE headers ${prefix}/include/eccd/*.hpp)
list(LENGTH headers n)
if(n LESS 100)
  message(FATAL_ERROR "install: only ${n} headers under ${prefix}/include/eccd")
endif()
foreach(h ${headers})
  file(STRINGS ${h} bad REGEX "#[ \t]*include[ \t]*\"(number|kernel|solution|floating|exact|certified|io|certificate|api)/")
  if(bad)
    message(FATAL_ERROR "install: ${h} includes a layer without the eccd/ prefix: ${bad}")
  endif()
endforeach()
message(STATUS "install: ${n} headers under include/eccd/, each including eccd's others as \"eccd/<layer>/...\"")

# 2. find_package(eccd).
set(b ${WORK_DIR}/find)
step("find_package: configure" ${CMAKE_COMMAND} -S ${ECCD_SOURCE_DIR}/tests/package/consumer -B ${b} ${common} -DCMAKE_PREFIX_PATH=${prefix})
step("find_package: build" ${CMAKE_COMMAND} --build ${b} -j2)
run_consumer("find_package" ${b} "beside eccd: the consumer's own kernel/answer.hpp, the consumer's own api/solve.hpp")

# 3. add_subdirectory(eccd): only the libraries app links are built. Header dependencies by CMake's scanner,
# as eccd's own build has them (CMakeLists.txt, CMAKE_DEPENDS_USE_COMPILER): the same compile commands, so
# the libraries' compilations are ccache hits of the build under test instead of a second full build.
set(b ${WORK_DIR}/subdir)
step("add_subdirectory: configure" ${CMAKE_COMMAND} -S ${ECCD_SOURCE_DIR}/tests/package/consumer -B ${b} ${common}
     -DECCD_SOURCE=${ECCD_SOURCE_DIR} -DBUILD_TESTING=OFF -DECCD_WERROR=${ECCD_WERROR}
     -DCMAKE_DEPENDS_USE_COMPILER=OFF)
step("add_subdirectory: build" ${CMAKE_COMMAND} --build ${b} -j2 --target app)
run_consumer("add_subdirectory" ${b})
foreach(f eccd/eccd eccd/eccd_tests eccd/python)
  if(EXISTS ${b}/${f})
    message(FATAL_ERROR "add_subdirectory: ${b}/${f} was built: a subproject builds only the libraries app needs")
  endif()
endforeach()
