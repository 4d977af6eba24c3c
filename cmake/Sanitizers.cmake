# -DDYNCONTACT_SANITIZE=address,undefined builds everything with those sanitizers;
# -DDYNCONTACT_SANITIZE_SKIP=alignment,null leaves out those checks (scripts/test.sh --sanitize:
# they tripled gcc's compile time on Eigen-heavy sources).
set(DYNCONTACT_SANITIZE "" CACHE STRING "Comma-separated sanitizers (address, undefined, ...)")
set(DYNCONTACT_SANITIZE_SKIP "" CACHE STRING "Comma-separated sanitizer checks left out (-fno-sanitize=...)")
if(DYNCONTACT_SANITIZE)
  add_compile_options(-fsanitize=${DYNCONTACT_SANITIZE} -fno-omit-frame-pointer)
  add_link_options(-fsanitize=${DYNCONTACT_SANITIZE})
  if(DYNCONTACT_SANITIZE_SKIP)
    add_compile_options(-fno-sanitize=${DYNCONTACT_SANITIZE_SKIP})
  endif()
endif()
