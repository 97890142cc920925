# scallop_perf_guard (perf_guard_main.cpp): the workload scripts/perf-guard.sh counts
# instructions on under callgrind; built into the build folder's top
# (build/scallop_perf_guard). Included by CMakeLists.txt, and by
# scripts/perf-guard.sh --against REV into a checkout of REV, so the same driver measures
# both trees; hence the fallbacks for older layouts (one `scallop_tools` library, flat
# tools/ headers) and this file's own paths.
add_executable(scallop_perf_guard ${CMAKE_CURRENT_LIST_DIR}/perf_guard_main.cpp)
if(TARGET scallop_run)
  # libfmt first: OpenImageIO's headers compile fmt's functions into height_export.o,
  # and the linker would pull that member (and OpenImageIO with it) to resolve the
  # readers' fmt calls. Seen first, libfmt resolves them; the rest is linked as needed.
  target_link_libraries(scallop_perf_guard PRIVATE -Wl,--no-as-needed
                        $<TARGET_LINKER_FILE:fmt::fmt> -Wl,--as-needed scallop_run TBB::tbb)
else()
  target_link_libraries(scallop_perf_guard PRIVATE scallop_tools TBB::tbb)
  target_include_directories(scallop_perf_guard PRIVATE ${PROJECT_SOURCE_DIR}/tools)
endif()
set_target_properties(scallop_perf_guard PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR})
