# Writes what the manual pages and the shell completion of prisca-cli are made of, from the
# program's own --help texts and its catalogs, so neither can drift from the program:
#   prisca-cli.h2m   help2man's include file: a COMMANDS section with every command's --help
#   prisca-cli.bash  the bash completion: commands, each command's options, plant and method
#                    names, method parameter names (--param NAME=)
# cmake -DCLI=path/to/prisca-cli -DOUT_DIR=dir -P GenerateCliDocs.cmake
cmake_minimum_required(VERSION 3.24)
foreach(required CLI OUT_DIR)
    if(NOT DEFINED ${required})
        message(FATAL_ERROR "GenerateCliDocs.cmake: -D${required}=... is required")
    endif()
endforeach()

function(run_cli out)
    execute_process(COMMAND ${CLI} ${ARGN} OUTPUT_VARIABLE text ERROR_VARIABLE error
                    RESULT_VARIABLE result)
    if(NOT result EQUAL 0)
        message(FATAL_ERROR "prisca-cli ${ARGN}: exit ${result}: ${error}")
    endif()
    set(${out} "${text}" PARENT_SCOPE)
endfunction()

# roff: a backslash is \e, a line starting with . or ' would be a request.
function(roff_escape out text)
    string(REPLACE "\\" "\\e" text "${text}")
    string(REGEX REPLACE "(^|\n)([.'])" "\\1\\\\&\\2" text "${text}")
    set(${out} "${text}" PARENT_SCOPE)
endfunction()

run_cli(main_help --help)
string(FIND "${main_help}" "Commands:\n" start)
string(SUBSTRING "${main_help}" ${start} -1 commands_block)
string(FIND "${commands_block}" "\n\n" end)
string(SUBSTRING "${commands_block}" 0 ${end} commands_block)
string(REGEX MATCHALL "\n  [a-z][a-z0-9-]* " command_lines "${commands_block}")
set(commands "")
foreach(line IN LISTS command_lines)
    string(STRIP "${line}" name)
    list(APPEND commands "${name}")
endforeach()
list(LENGTH commands count)
if(count LESS 10)
    message(FATAL_ERROR "prisca-cli --help lists ${count} commands: not the list expected")
endif()

run_cli(catalog methods --format json)
string(JSON plant_count LENGTH "${catalog}" plants)
math(EXPR last "${plant_count} - 1")
set(plants "")
foreach(i RANGE ${last})
    string(JSON plant GET "${catalog}" plants ${i})
    list(APPEND plants "${plant}")
endforeach()
string(JSON method_count LENGTH "${catalog}" methods)
math(EXPR last "${method_count} - 1")
set(methods "")
set(parameters "")
foreach(i RANGE ${last})
    string(JSON id GET "${catalog}" methods ${i} id)
    list(APPEND methods "${id}")
    string(JSON parameter_count LENGTH "${catalog}" methods ${i} parameters)
    if(parameter_count GREATER 0)
        math(EXPR last_parameter "${parameter_count} - 1")
        foreach(j RANGE ${last_parameter})
            string(JSON parameter GET "${catalog}" methods ${i} parameters ${j} name)
            list(APPEND parameters "${parameter}=")
        endforeach()
    endif()
endforeach()
list(REMOVE_DUPLICATES parameters)

set(h2m "[COMMANDS]\nEach command has options of its own; \\fBprisca\\-cli\\fR \\fIcommand\\fR \\fB\\-\\-help\\fR prints them, as below.\n")
set(cases "")
set(value_options "")
foreach(command IN LISTS commands)
    run_cli(help ${command} --help)
    # The usage and the description as filled text (they are long lines); the option table as
    # --help aligns it.
    string(FIND "${help}" "\nOptions:\n" options_at)
    string(SUBSTRING "${help}" 0 ${options_at} head)
    math(EXPR options_at "${options_at} + 1")
    string(SUBSTRING "${help}" ${options_at} -1 table)
    roff_escape(head "${head}")
    roff_escape(table "${table}")
    string(REPLACE "\n" "\n.br\n" head "${head}")
    string(APPEND h2m ".SS ${command}\n${head}\n.nf\n${table}.fi\n")
    string(REPLACE ";" "," listable "${help}")  # a ; would split CMake's list
    string(REGEX MATCHALL "\n  (-[a-z], )?--[a-z0-9-]+( <[^>]+>)?" option_lines "${listable}")
    set(options "")
    foreach(line IN LISTS option_lines)
        string(REGEX MATCH "--[a-z0-9-]+" option "${line}")
        if(option STREQUAL "--help-all")
            continue()
        endif()
        list(APPEND options "${option}")
        if(line MATCHES "<")
            list(APPEND value_options "${option}")
        endif()
    endforeach()
    list(JOIN options " " options)
    string(APPEND cases "        ${command}) options=\"${options}\" ;;\n")
endforeach()
list(REMOVE_DUPLICATES value_options)

string(APPEND h2m "[FILES]\n.TP\n\\fI~/.config/PRISCA Lab/prisca.conf\\fR\nThe window's settings (the rig's camera, port, protocol, channel map, fence).\n")
string(APPEND h2m ".TP\n\\fI~/.local/share/PRISCA Lab/prisca/\\fR\nRecordings and trial bundles (\\fBprisca\\-cli doctor\\fR lists the folders in use).\n")
string(APPEND h2m "[SEE ALSO]\n\\fBprisca\\fR(1). The operator guide and docs/install.md in \\fI/usr/share/doc/prisca\\-lab/\\fR.\n")
file(WRITE ${OUT_DIR}/prisca-cli.h2m "${h2m}")

list(JOIN commands " " commands)
list(JOIN plants " " plants)
list(JOIN methods " " methods)
list(JOIN parameters " " parameters)
string(REPLACE ";" "|" value_pattern "${value_options}")
file(WRITE ${OUT_DIR}/prisca-cli.bash "# bash completion for prisca-cli: generated from its --help and its catalogs when it was
# built (packaging/GenerateCliDocs.cmake); do not edit.
_prisca_cli() {
    local cur prev words cword
    _init_completion || return
    local commands=\"${commands}\"
    local command=\"\" i
    for ((i = 1; i < cword; i++)); do
        case \"\${words[i]}\" in
            -*) ;;
            *) command=\"\${words[i]}\"; break ;;
        esac
    done
    if [[ -z \$command ]]; then
        COMPREPLY=(\$(compgen -W \"\$commands --help --version\" -- \"\$cur\"))
        return
    fi
    case \"\$prev\" in
        --plant) COMPREPLY=(\$(compgen -W \"${plants}\" -- \"\$cur\")); return ;;
        --method) COMPREPLY=(\$(compgen -W \"${methods}\" -- \"\$cur\")); return ;;
        --param)
            COMPREPLY=(\$(compgen -W \"${parameters}\" -- \"\$cur\"))
            compopt -o nospace 2>/dev/null
            return
            ;;
        --format) COMPREPLY=(\$(compgen -W \"text json md csv\" -- \"\$cur\")); return ;;
        ${value_pattern}) _filedir; return ;;
    esac
    local options=\"\"
    case \"\$command\" in
${cases}    esac
    if [[ \$cur == -* ]]; then
        COMPREPLY=(\$(compgen -W \"\$options\" -- \"\$cur\"))
    else
        _filedir
    fi
}
complete -F _prisca_cli prisca-cli
")
