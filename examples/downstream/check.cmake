# Configures, builds and runs the downstream example against this source tree (ctest: downstream_add_subdirectory).
#   cmake -DSOURCE=... -DBUILD=... [-DLAUNCHER=ccache] [-DWERROR=ON] -P check.cmake
set(args -S ${SOURCE}/examples/downstream -B ${BUILD} -G Ninja -DCMAKE_BUILD_TYPE=Release -DSGTLLC_SOURCE_DIR=${SOURCE}
    -DSGTLLC_WITH_BACKEND=OFF -DSGTLLC_WITH_FAISS=OFF -DSGTLLC_WERROR=${WERROR})
if(LAUNCHER)
  list(APPEND args -DCMAKE_CXX_COMPILER_LAUNCHER=${LAUNCHER})
endif()
foreach(step configure build run)
  if(step STREQUAL "configure")
    set(command ${CMAKE_COMMAND} ${args})
  elseif(step STREQUAL "build")
    set(command ${CMAKE_COMMAND} --build ${BUILD} -j 2)
  else()
    set(command ${BUILD}/uses_sgtllc ${SOURCE}/data/kitti/00/velodyne/004501.bin
                ${SOURCE}/data/kitti/00/velodyne/000052.bin)
  endif()
  execute_process(COMMAND ${command} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT step STREQUAL "build")
    message("${out}")  # the configure summary and the program's answer
  endif()
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "downstream ${step} failed (${status}):\n${out}\n${err}")
  endif()
endforeach()
