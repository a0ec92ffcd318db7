# cli.eval_grid_tif_equals_asc: band 1 of a GeoTIFF, printed by geotiff_dump in the ESRI ASCII
# layout, must equal the .asc that `tspline eval` wrote of the same grid byte for byte.
#   cmake -DDUMP=geotiff_dump -DTIF=a.tif -DASC=a.asc -DOUT=dump.asc -P geotiff_compare.cmake
execute_process(COMMAND ${DUMP} ${TIF} RESULT_VARIABLE code OUTPUT_FILE ${OUT})
if(NOT code EQUAL 0)
  message(FATAL_ERROR "geotiff_dump ${TIF} failed (${code})")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${OUT} ${ASC} RESULT_VARIABLE differ)
if(NOT differ EQUAL 0)
  file(READ ${OUT} dumped)
  message(FATAL_ERROR "${TIF} differs from ${ASC}; its band 1:\n${dumped}")
endif()
