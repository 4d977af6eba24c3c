# Warnings for the project's own targets: -Wall -Wextra and a few more, clean by policy.
function(dyncontact_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow=local -Wnon-virtual-dtor)
endfunction()
