# Checks that every lookup table in the fixed-point library sits in read-only data (nm type
# R or r), i.e. that the compiler built it at compile time rather than at start-up.
#   cmake -DNM=<nm> -DLIB=<libnoneuclid_fixed.a> -P tables_readonly.cmake
execute_process(COMMAND ${NM} -C ${LIB} OUTPUT_VARIABLE out RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${NM} failed on ${LIB}")
endif()
string(REGEX MATCHALL "[0-9a-fA-F]+ [A-Za-z] noneuclid::fx::tables::[a-z0-9_]+" lines "${out}")
list(LENGTH lines n)
if(n LESS 10)
    message(FATAL_ERROR "expected at least 10 table symbols in ${LIB}, found ${n}:\n${out}")
endif()
foreach(line IN LISTS lines)
    if(NOT line MATCHES " [Rr] noneuclid::fx::tables::")
        message(FATAL_ERROR "table not in read-only data: ${line}")
    endif()
endforeach()
message(STATUS "${n} table symbols, all in read-only data")
