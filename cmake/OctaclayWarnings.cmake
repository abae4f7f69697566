# octaclay_set_warnings(<target>): the project's warning set, -Werror when OCTACLAY_WERROR is on.
function(octaclay_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
                                           -Wno-sign-conversion)
  if(OCTACLAY_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
  if(OCTACLAY_SANITIZE)
    target_compile_options(${target} PRIVATE -fsanitize=address,undefined -fno-omit-frame-pointer)
    target_link_options(${target} PRIVATE -fsanitize=address,undefined)
  endif()
endfunction()
