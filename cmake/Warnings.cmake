# Warnings for the project's own targets: -Wall -Wextra and a few more, clean by policy
# (clang, the fuzz build, spells gcc's -Wshadow=local as -Wshadow-uncaptured-local).
function(dyncontact_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic
                                           $<IF:$<CXX_COMPILER_ID:GNU>,-Wshadow=local,-Wshadow-uncaptured-local>
                                           -Wnon-virtual-dtor)
endfunction()
