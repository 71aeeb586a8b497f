# fxlab_add_lesson(<dir-name>): one executable per lesson folder, named fxlab-<dir-name> with the
# first underscore turned into a dash and the rest kept (01_program_objects -> fxlab-01-program-objects).
function(fxlab_add_lesson dir)
  string(REPLACE "_" "-" exe_name "fxlab-${dir}")
  file(GLOB_RECURSE sources CONFIGURE_DEPENDS "${CMAKE_CURRENT_SOURCE_DIR}/${dir}/*.cpp")
  add_executable(${exe_name} ${sources})
  target_link_libraries(${exe_name} PRIVATE fxcommon fx_warnings)
  set_property(GLOBAL APPEND PROPERTY FXLAB_LESSON_TARGETS ${exe_name})
endfunction()
