# pm_set_warnings(<target>): the warning set every target of ours is built with.
function(pm_set_warnings target)
  target_compile_options(${target} PRIVATE
    $<$<CXX_COMPILER_ID:GNU,Clang>:-Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor
                                   -Wold-style-cast -Wcast-align -Woverloaded-virtual
                                   -Wconversion -Wno-sign-conversion
                                   -Wformat=2>)
endfunction()
