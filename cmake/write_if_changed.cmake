# write_if_changed(PATH TEXT): writes TEXT to PATH only when it differs from what PATH holds, so
# that what depends on a generated file is not rebuilt needlessly.
function(write_if_changed path text)
    if(EXISTS ${path})
        file(READ ${path} previous)
        if(previous STREQUAL text)
            return()
        endif()
    endif()
    file(WRITE ${path} "${text}")
endfunction()
