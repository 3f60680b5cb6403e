# oasis_set_warnings(TARGET): the warning policy for every target we own.
# Third-party headers come in as SYSTEM includes, so -Werror applies to our code only.
function(oasis_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Werror -Wshadow -Wnon-virtual-dtor
                                           -Wold-style-cast -Wcast-align -Woverloaded-virtual)
endfunction()
