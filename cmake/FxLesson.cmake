# fxlab_add_lesson(<dir-name>): one executable per lesson folder, named fxlab-<dir-name> with the
# underscores turned into dashes (01_program_objects -> fxlab-01-program-objects).
#
# A lesson is one folder: its .cpp files (the last line of one of them is FX_LESSON, app/runner.hpp),
# lesson.md and lesson.ja.md, its words (words.en, words.ja: base/words.hpp), and, found by the lesson's number, its shaders (shaders/lessons/<dir>/)
# and its scene (res/scenes/NN_*.json). The text, shaders and scene are sources of the target too
# (not compiled), so an IDE shows the whole lesson in one place. The folder's name gives the lesson
# its number and slug (FXLAB_LESSON_NUMBER, FXLAB_LESSON_SLUG): written once, and checked here.
function(fxlab_add_lesson dir)
  if(NOT dir MATCHES "^([0-9][0-9])_([a-z0-9]+(_[a-z0-9]+)*)$")
    message(FATAL_ERROR "lessons/${dir}: a lesson folder is named NN_name (two digits, an underscore, then lower-case words joined by underscores), like 04_colour_matrix")
  endif()
  set(number_text "${CMAKE_MATCH_1}")
  math(EXPR number "${number_text}")  # "08" is 8, not an octal literal
  string(REPLACE "_" "-" slug "${CMAKE_MATCH_2}")
  get_property(numbers GLOBAL PROPERTY FXLAB_LESSON_NUMBERS)
  if("${number}" IN_LIST numbers)
    message(FATAL_ERROR "lessons/${dir}: another lesson folder already has the number ${number_text}")
  endif()
  set_property(GLOBAL APPEND PROPERTY FXLAB_LESSON_NUMBERS "${number}")

  set(folder "${CMAKE_CURRENT_SOURCE_DIR}/${dir}")
  file(GLOB_RECURSE sources CONFIGURE_DEPENDS "${folder}/*.cpp")
  file(GLOB headers CONFIGURE_DEPENDS "${folder}/*.hpp")
  file(GLOB texts CONFIGURE_DEPENDS "${folder}/*.md" "${folder}/words.*")
  file(GLOB_RECURSE shaders CONFIGURE_DEPENDS "${FXLAB_ROOT}/shaders/lessons/${dir}/*")
  file(GLOB scenes CONFIGURE_DEPENDS "${FXLAB_ROOT}/res/scenes/${number_text}_*.json")
  set(shown ${texts} ${shaders} ${scenes})
  set_source_files_properties(${shown} PROPERTIES HEADER_FILE_ONLY ON)

  string(REPLACE "_" "-" exe_name "fxlab-${dir}")
  add_executable(${exe_name} ${sources} ${headers} ${shown})
  target_compile_definitions(${exe_name} PRIVATE FXLAB_LESSON_NUMBER=${number} FXLAB_LESSON_SLUG="${slug}")
  target_link_libraries(${exe_name} PRIVATE fxcommon fx_warnings)
  # Windows: a GUI program, so that a double-click opens the lesson's window and no console beside it
  # (from a console it still writes there: app/process_start_win.cpp).
  set_target_properties(${exe_name} PROPERTIES WIN32_EXECUTABLE ON)
  if(MSVC)  # a GUI program whose entry is still main() (mingw-w64 does this by itself)
    target_link_options(${exe_name} PRIVATE /ENTRY:mainCRTStartup)
  endif()
  set_property(GLOBAL APPEND PROPERTY FXLAB_LESSON_TARGETS ${exe_name})
endfunction()
