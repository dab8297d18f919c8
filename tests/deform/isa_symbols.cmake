# The copies of the numeric supernodal factorization compiled for AVX2 and AVX-512 must not
# define any weak (inline or template) symbol that another file could also define: the
# linker keeps one of them, and if it kept the wide copy a CPU without AVX would run it.
# Only Eigen under its renamed namespace and the copy's own namespace may appear.
# Run as: cmake -DNM=<nm> -DOBJECTS=<object files, ;-separated> -P isa_symbols.cmake
set(_checked 0)
foreach(_object IN LISTS OBJECTS)
  if(NOT _object MATCHES "numeric_avx(2|512)\\.cpp\\.o(bj)?$")
    continue()
  endif()
  math(EXPR _checked "${_checked} + 1")
  execute_process(COMMAND ${NM} -C --defined-only ${_object} OUTPUT_VARIABLE _symbols
                  RESULT_VARIABLE _result)
  if(NOT _result EQUAL 0)
    message(FATAL_ERROR "${NM} failed on ${_object}")
  endif()
  string(REPLACE "\n" ";" _lines "${_symbols}")
  foreach(_line IN LISTS _lines)
    if(_line MATCHES "^[0-9a-fA-F]* [WVuw] (.*)$")
      set(_name "${CMAKE_MATCH_1}")
      if(NOT _name MATCHES "finbook_eigen_(avx2|avx512)|finbook::deform::supernodal::avx(2|512)|^DW\\.ref\\.__gxx_personality_v0$")
        message(SEND_ERROR "${_object}: weak symbol shared with other files: ${_name}")
      endif()
    endif()
  endforeach()
endforeach()
if(_checked EQUAL 0)
  message(FATAL_ERROR "no AVX object among: ${OBJECTS}")
endif()
message(STATUS "${_checked} instruction-set objects checked")
