# Runs PROGRAM with the arguments ARGS (a ;-list) and writes its standard output to OUTPUT;
# fails the build when the program fails. Usage:
#   cmake -DPROGRAM=... -DARGS=... -DOUTPUT=... -P output_to_file.cmake
execute_process(COMMAND ${PROGRAM} ${ARGS} OUTPUT_FILE ${OUTPUT}.tmp RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  file(REMOVE ${OUTPUT}.tmp)
  message(FATAL_ERROR "${PROGRAM} ${ARGS} failed: ${status}")
endif()
file(RENAME ${OUTPUT}.tmp ${OUTPUT})
