# sgtllc_add_library(TARGET EXPORT_NAME [STATIC|SHARED] SOURCES...): one of the libraries the project installs, with
# what each of them repeats: the alias sgtllc::EXPORT_NAME a downstream project links (the same name find_package
# gives), the public headers of include/ (from the source tree; once installed, install(TARGETS … INCLUDES
# DESTINATION) in the top CMakeLists.txt names the prefix's), position-independent code (the Python module and
# shared builds link them) and the project's warnings.

function(sgtllc_add_library target export_name)
  add_library(${target} ${ARGN})
  add_library(sgtllc::${export_name} ALIAS ${target})
  target_include_directories(${target} PUBLIC $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/include>)
  set_target_properties(${target} PROPERTIES POSITION_INDEPENDENT_CODE ON EXPORT_NAME ${export_name})
  sgtllc_set_warnings(${target})
endfunction()
