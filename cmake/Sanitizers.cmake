# -DDYNCONTACT_SANITIZE=address,undefined builds everything with those sanitizers.
set(DYNCONTACT_SANITIZE "" CACHE STRING "Comma-separated sanitizers (address, undefined, ...)")
if(DYNCONTACT_SANITIZE)
  add_compile_options(-fsanitize=${DYNCONTACT_SANITIZE} -fno-omit-frame-pointer)
  add_link_options(-fsanitize=${DYNCONTACT_SANITIZE})
endif()
