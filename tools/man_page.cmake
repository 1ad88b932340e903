# One man page from frustum's help text (cmake -P, called by the `man` target):
#   cmake -DHELP2MAN=… -DFRUSTUM=… -DNAME=frustum-solve -DHELP_OPTION="solve --help"
#         -DDESCRIPTION="…" -DOUT=man/frustum-solve.1.gz -P tools/man_page.cmake
# help2man names every page after the program; a subcommand's page is renamed frustum-SUB.
get_filename_component(dir ${OUT} DIRECTORY)
file(MAKE_DIRECTORY ${dir})
set(page ${dir}/${NAME}.1)
execute_process(COMMAND ${HELP2MAN} --no-info --section=1 --name=${DESCRIPTION} --help-option=${HELP_OPTION}
                        --version-option=--version --output=${page} ${FRUSTUM}
                RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "help2man failed for ${NAME}")
endif()
file(READ ${page} text)
string(TOUPPER ${NAME} upper)
string(REPLACE ".TH FRUSTUM " ".TH ${upper} " text "${text}")
string(REPLACE ".SH NAME\nfrustum " ".SH NAME\n${NAME} " text "${text}")
file(WRITE ${page} "${text}")
execute_process(COMMAND gzip -9nf ${page} RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "gzip failed for ${page}")
endif()
