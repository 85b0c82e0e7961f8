# Run after lcm-gen (cmake -DDIR=<dir of the generated .hpp files> -P fix_string_decode.cmake):
# makes the generated C++ decode refuse a string whose length field is below 1.
#
# lcm-gen 1.3.1 decodes a string as
#     if(__s_len__ > maxlen - pos) return -1;
#     this->s.assign(buf + offset + pos, __s_len__ - 1);
# The length counts the terminating \0, so a valid one is at least 1. A length of 0 or a negative
# one passes the check: assign() then gets length - 1, which throws std::length_error (thrown
# through LCM's C dispatch, it terminates the program) or, for INT32_MIN, overflows to
# INT32_MAX and copies 2 GiB from past the buffer. Found by tests/fuzz/fuzz_lcm on status_t.
file(GLOB headers ${DIR}/*.hpp)
foreach(header ${headers})
  file(READ ${header} text)
  string(REGEX REPLACE "if\\(__([A-Za-z0-9_]+)_len__ > maxlen - pos\\) return -1;"
         "if(__\\1_len__ < 1 || __\\1_len__ > maxlen - pos) return -1;" fixed "${text}")
  if(NOT fixed STREQUAL text)
    file(WRITE ${header} "${fixed}")
  endif()
endforeach()
