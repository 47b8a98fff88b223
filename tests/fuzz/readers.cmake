# The file-reader fuzz targets (GSHHS, shapefile, lon/lat text, loops2, netCDF grid,
# ESRI grid), included from tests/fuzz/CMakeLists.txt.
#  - fuzz_replay_<reader> (always, any compiler): the reader's fuzz entry over
#    corpus_<reader>/ and crashes_<reader>/; a CTest test each.
#  - fuzz_<reader> (STEREOMESH_FUZZ=ON, clang): the libFuzzer binary; CTest test
#    fuzz_short_<reader> runs it a fixed number of runs from a fixed seed (run.sh).
set(sm_fuzz_readers gshhs lonlat_text loops2 shapefile netcdf esri)
# Runs per reader for fuzz_short_<reader>: under 30 s on one core each (measured with
# ASan+UBSan; the file-writing readers are the slow ones).
set(sm_fuzz_runs_gshhs 40000)
set(sm_fuzz_runs_lonlat_text 40000)
set(sm_fuzz_runs_loops2 40000)
set(sm_fuzz_runs_shapefile 8000)
set(sm_fuzz_runs_netcdf 8000)
set(sm_fuzz_runs_esri 40000)

add_library(sm_fuzz_temp_file STATIC fuzz_temp_file.cpp)
target_link_libraries(sm_fuzz_temp_file PRIVATE sm_warnings)
foreach(r IN LISTS sm_fuzz_readers)
  add_library(sm_fuzz_${r}_entry STATIC fuzz_${r}_entry.cpp)
  target_include_directories(sm_fuzz_${r}_entry PUBLIC "${CMAKE_CURRENT_SOURCE_DIR}")
  target_link_libraries(sm_fuzz_${r}_entry PUBLIC sm_coast sm_field sm_fuzz_temp_file PRIVATE sm_warnings)
endforeach()

add_executable(fuzz_readers_replay replay_readers_main.cpp)
foreach(r IN LISTS sm_fuzz_readers)
  target_link_libraries(fuzz_readers_replay PRIVATE sm_fuzz_${r}_entry)
  add_test(NAME fuzz_replay_${r}
           COMMAND fuzz_readers_replay ${r} "${CMAKE_CURRENT_SOURCE_DIR}/corpus_${r}"
                   "${CMAKE_CURRENT_SOURCE_DIR}/crashes_${r}"
           WORKING_DIRECTORY "${CMAKE_CURRENT_BINARY_DIR}")
endforeach()
target_link_libraries(fuzz_readers_replay PRIVATE sm_warnings)

if(STEREOMESH_FUZZ)
  foreach(lib sm_fuzz_temp_file)
    target_compile_options(${lib} PRIVATE ${sm_fuzz_flags} -fsanitize=fuzzer-no-link)
  endforeach()
  target_link_options(fuzz_readers_replay PRIVATE ${sm_fuzz_flags})
  foreach(r IN LISTS sm_fuzz_readers)
    target_compile_options(sm_fuzz_${r}_entry PRIVATE ${sm_fuzz_flags} -fsanitize=fuzzer-no-link)
    add_executable(fuzz_${r} fuzz_${r}.cpp)
    target_link_libraries(fuzz_${r} PRIVATE sm_fuzz_${r}_entry)
    target_compile_options(fuzz_${r} PRIVATE ${sm_fuzz_flags} -fsanitize=fuzzer)
    target_link_options(fuzz_${r} PRIVATE ${sm_fuzz_flags} -fsanitize=fuzzer)
    add_test(NAME fuzz_short_${r}
             COMMAND ${CMAKE_COMMAND} -E env SM_FUZZ_RUNS=${sm_fuzz_runs_${r}} SM_FUZZ_SEED=1
                     bash "${CMAKE_CURRENT_SOURCE_DIR}/run.sh" --no-build --target ${r} 300
                     "$<TARGET_FILE:fuzz_${r}>"
             WORKING_DIRECTORY "${CMAKE_CURRENT_BINARY_DIR}")
    set_tests_properties(fuzz_short_${r} PROPERTIES TIMEOUT 600)
  endforeach()
endif()
