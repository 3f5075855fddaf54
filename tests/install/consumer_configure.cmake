# The configure arguments of a consumer project built against the installed package (run_consumer.cmake,
# headers_alone.cmake): only WTC_PREFIX may provide wtc (no user or system registry), and the generator, make
# program and compiler are this build's own (a package is built with and for one compiler); they set nothing in
# the project itself. Sets consumer_configure_args for a project in source_dir, built in binary_dir.
function(wtc_consumer_configure_args source_dir binary_dir)
  set(args -S ${source_dir} -B ${binary_dir} -DCMAKE_PREFIX_PATH=${WTC_PREFIX}
    -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF -DCMAKE_FIND_USE_SYSTEM_PACKAGE_REGISTRY=OFF)
  if(WTC_GENERATOR)
    list(APPEND args -G ${WTC_GENERATOR})
  endif()
  if(WTC_MAKE_PROGRAM)
    list(APPEND args -DCMAKE_MAKE_PROGRAM=${WTC_MAKE_PROGRAM})
  endif()
  if(WTC_CXX_COMPILER)
    list(APPEND args -DCMAKE_CXX_COMPILER=${WTC_CXX_COMPILER})
  endif()
  set(consumer_configure_args ${args} PARENT_SCOPE)
endfunction()
