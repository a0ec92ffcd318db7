# ctest install.find_package: cmake --install BUILD_DIR --prefix PREFIX, then configure, build
# and run the outside project SOURCE_DIR/test/install against PREFIX only.
# -DBUILD_DIR=... -DSOURCE_DIR=... -DPREFIX=... -DGENERATOR=... -DLIBDIR=... [-DPYTHON=... -DPYTHON_DIR=...]
foreach(var BUILD_DIR SOURCE_DIR PREFIX GENERATOR LIBDIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "run_install_test.cmake: ${var} is not set")
  endif()
endforeach()

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT code EQUAL 0)
    string(REPLACE ";" " " command "${ARGN}")
    message(FATAL_ERROR "failed (${code}): ${command}\n${out}")
  endif()
  message(STATUS "${out}")
endfunction()

file(REMOVE_RECURSE ${PREFIX} ${PREFIX}-project)
run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${PREFIX})
foreach(file include/CGAL/Triangular_spline/Bezier_triangle.h
             ${LIBDIR}/cmake/Triangular_spline/Triangular_splineConfig.cmake
             ${LIBDIR}/cmake/Triangular_spline/Triangular_splineConfigVersion.cmake
             ${LIBDIR}/cmake/Triangular_spline/Triangular_splineTargets.cmake)
  if(NOT EXISTS ${PREFIX}/${file})
    message(FATAL_ERROR "not installed: ${PREFIX}/${file}")
  endif()
endforeach()

# Only the prefix: CMAKE_PREFIX_PATH, never the build tree.
run(${CMAKE_COMMAND} -S ${SOURCE_DIR}/test/install -B ${PREFIX}-project -G ${GENERATOR}
    -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH=${PREFIX})
run(${CMAKE_COMMAND} --build ${PREFIX}-project)
run(${PREFIX}-project/install_test)

# The Python module from the prefix, when it was built.
if(PYTHON AND PYTHON_DIR)
  run(${CMAKE_COMMAND} -E env PYTHONPATH=${PREFIX}/${PYTHON_DIR} PYTHONDONTWRITEBYTECODE=1
      ${PYTHON} ${SOURCE_DIR}/test/install/check_python.py ${PREFIX})
endif()
