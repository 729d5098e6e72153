# Applies the project's warning flags to one of our own targets (never to third-party code).
function(sgtllc_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor)
  if(SGTLLC_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()
