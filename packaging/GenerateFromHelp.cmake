# Writes the man page and the bash completion from the program's own --help, at build time, so
# neither can drift from the command line: a new subcommand or option appears in both at the next
# build. Usage:
#   cmake -DRADIANT=<radiant executable> -DMAN_PAGE=<radiant.1> -DCOMPLETION=<radiant> -P GenerateFromHelp.cmake
# The help is CLI11's layout: a description line, "Usage: ...", then sections ("Options:") whose
# entries start at column 2 (the option, then two or more spaces, then its description) and
# continue on lines indented further.
foreach(variable RADIANT MAN_PAGE COMPLETION)
  if(NOT ${variable})
    message(FATAL_ERROR "GenerateFromHelp.cmake: pass -D${variable}=...")
  endif()
endforeach()

# Runs radiant with the given arguments; its standard output, which must be there.
function(run_radiant out_var)
  execute_process(COMMAND ${RADIANT} ${ARGN} OUTPUT_VARIABLE output RESULT_VARIABLE status ERROR_VARIABLE errors)
  if(NOT status EQUAL 0 OR output STREQUAL "")
    message(FATAL_ERROR "GenerateFromHelp.cmake: `radiant ${ARGN}` failed (${status}): ${errors}")
  endif()
  set(${out_var} "${output}" PARENT_SCOPE)
endfunction()

# CMake lists split at ';' and group at '[' ']': help text may hold either, so they travel encoded.
function(help_lines out_var text)
  string(REPLACE ";" "<semicolon>" text "${text}")
  string(REPLACE "[" "<lbracket>" text "${text}")
  string(REPLACE "]" "<rbracket>" text "${text}")
  string(REGEX REPLACE "\n+$" "" text "${text}")
  string(REPLACE "\n" ";" lines "${text}")
  set(${out_var} "${lines}" PARENT_SCOPE)
endfunction()
function(decode out_var text)
  string(REPLACE "<semicolon>" ";" text "${text}")
  string(REPLACE "<lbracket>" "[" text "${text}")
  string(REPLACE "<rbracket>" "]" text "${text}")
  set(${out_var} "${text}" PARENT_SCOPE)
endfunction()

# roff: backslashes doubled, hyphens as minus signs (so options can be searched and copied), and a
# line may not start with a control character.
function(roff out_var text)
  decode(text "${text}")
  string(REPLACE "\\" "\\\\" text "${text}")
  string(REPLACE "-" "\\-" text "${text}")
  if(text MATCHES "^[.']")
    set(text "\\&${text}")
  endif()
  set(${out_var} "${text}" PARENT_SCOPE)
endfunction()

# Parses one help text into <prefix>_DESCRIPTION, <prefix>_USAGE and, per section, the entries:
# <prefix>_SECTIONS (names), <prefix>_<section>_COUNT, and for entry i <prefix>_<section>_<i>_SPEC and
# _TEXT (still encoded).
macro(parse_help prefix text)
  help_lines(_lines "${text}")
  set(${prefix}_DESCRIPTION "")
  set(${prefix}_USAGE "")
  set(${prefix}_SECTIONS "")
  set(_section "")
  set(_index -1)
  foreach(_line IN LISTS _lines)
    if(_line MATCHES "^Usage: (.*)$")
      set(${prefix}_USAGE "${CMAKE_MATCH_1}")
    elseif(_line MATCHES "^([A-Za-z]+):$")
      set(_section "${CMAKE_MATCH_1}")
      list(APPEND ${prefix}_SECTIONS "${_section}")
      set(${prefix}_${_section}_COUNT 0)
      set(_index -1)
    elseif(_section AND _line MATCHES "^  ([^ ].*)$")
      set(_entry "${CMAKE_MATCH_1}")
      math(EXPR _index "${_index} + 1")
      math(EXPR ${prefix}_${_section}_COUNT "${_index} + 1")
      if(_entry MATCHES "^([^ ]+( [^ ]+)*)  +(.*)$")
        set(${prefix}_${_section}_${_index}_SPEC "${CMAKE_MATCH_1}")
        set(${prefix}_${_section}_${_index}_TEXT "${CMAKE_MATCH_3}")
      else()
        set(${prefix}_${_section}_${_index}_SPEC "${_entry}")
        set(${prefix}_${_section}_${_index}_TEXT "")
      endif()
    elseif(_section AND _index GREATER -1 AND _line MATCHES "^   +(.*)$")
      string(STRIP "${${prefix}_${_section}_${_index}_TEXT} ${CMAKE_MATCH_1}" ${prefix}_${_section}_${_index}_TEXT)
    elseif(NOT _section AND ${prefix}_DESCRIPTION STREQUAL "" AND NOT _line STREQUAL "")
      set(${prefix}_DESCRIPTION "${_line}")
    endif()
  endforeach()
endmacro()

# An option's spec ("--method TEXT=gauss-seidel", "-h,--help", "--only TEXT:{a,b}",
# "--samples UINT=1000000 Excludes: --seconds"): its names, whether it takes a value, its choices.
function(option_parts spec names_var takes_value_var choices_var)
  decode(spec "${spec}")
  string(REGEX MATCH "^[^ ]+" names "${spec}")
  string(REPLACE "," ";" names "${names}")
  set(takes_value OFF)
  if(spec MATCHES "^[^ ]+ [A-Z]+")
    set(takes_value ON)
  endif()
  set(choices "")
  if(spec MATCHES ":{([^}]*)}")
    string(REPLACE "," " " choices "${CMAKE_MATCH_1}")
  endif()
  set(${names_var} "${names}" PARENT_SCOPE)
  set(${takes_value_var} ${takes_value} PARENT_SCOPE)
  set(${choices_var} "${choices}" PARENT_SCOPE)
endfunction()

run_radiant(version --version)
string(STRIP "${version}" version)
run_radiant(root_help --help)
parse_help(ROOT "${root_help}")
set(subcommands "")
if(ROOT_Subcommands_COUNT)
  math(EXPR last "${ROOT_Subcommands_COUNT} - 1")
  foreach(i RANGE ${last})
    list(APPEND subcommands "${ROOT_Subcommands_${i}_SPEC}")
  endforeach()
endif()
if(subcommands STREQUAL "")
  message(FATAL_ERROR "GenerateFromHelp.cmake: `radiant --help` lists no subcommands")
endif()
foreach(command IN LISTS subcommands)
  run_radiant(help ${command} --help)
  parse_help(SUB_${command} "${help}")
endforeach()

# ---- the man page --------------------------------------------------------------------------------
# The entries of one parsed section as .TP paragraphs.
function(man_entries out_var prefix section)
  set(page "")
  if(${prefix}_${section}_COUNT)
    math(EXPR last "${${prefix}_${section}_COUNT} - 1")
    foreach(i RANGE ${last})
      roff(spec "${${prefix}_${section}_${i}_SPEC}")
      roff(text "${${prefix}_${section}_${i}_TEXT}")
      string(APPEND page ".TP\n\\fB${spec}\\fR\n${text}\n")
    endforeach()
  endif()
  set(${out_var} "${page}" PARENT_SCOPE)
endfunction()

string(REGEX REPLACE "^[^:]*: " "" summary "${ROOT_DESCRIPTION}")
roff(summary "${summary}")
roff(version_roff "${version}")
set(page ".\\\" Generated at build time by packaging/GenerateFromHelp.cmake from `radiant --help`; do not edit.\n")
string(APPEND page ".TH RADIANT 1 \"\" \"${version_roff}\" \"User Commands\"\n")
# Option names must not be hyphenated at line ends, nor justified into gaps.
string(APPEND page ".nh\n.ad l\n")
string(APPEND page ".SH NAME\nradiant \\- ${summary}\n")
string(APPEND page ".SH SYNOPSIS\n")
roff(usage "${ROOT_USAGE}")
string(APPEND page "${usage}\n")
foreach(command IN LISTS subcommands)
  roff(usage "${SUB_${command}_USAGE}")
  string(APPEND page ".br\n${usage}\n")
endforeach()
string(APPEND page ".SH DESCRIPTION\nWithout a subcommand, \\fBradiant\\fR opens the lab's window on the scene, a built\\-in scene's name \
or a glTF file (.gltf, .glb). The subcommands run without a window. Exit status is 0 on success and 2 on bad arguments \
or bad input, with one line on standard error naming the file, the element and what is wrong.\n")
foreach(section IN LISTS ROOT_SECTIONS)
  string(TOUPPER "${section}" title)
  man_entries(entries ROOT "${section}")
  string(APPEND page ".SH ${title}\n${entries}")
endforeach()
foreach(command IN LISTS subcommands)
  roff(description "${SUB_${command}_DESCRIPTION}")
  string(APPEND page ".SH \"RADIANT ${command}\"\n${description}.\n")
  roff(usage "${SUB_${command}_USAGE}")
  string(APPEND page ".PP\n\\fBUsage:\\fR ${usage}\n")
  foreach(section IN LISTS SUB_${command}_SECTIONS)
    man_entries(entries SUB_${command} "${section}")
    string(APPEND page ".SS ${section}\n${entries}")
  endforeach()
endforeach()
string(APPEND page ".SH FILES\n.TP\n\\fI../share/radiant/assets/\\fR beside the executable\n\
The built\\-in scenes as glTF files (\\fI/usr/share/radiant/assets/\\fR when installed from the package).\n")
string(APPEND page ".SH ENVIRONMENT\n.TP\n\\fBRADIANT_UI_SCALE\\fR\nScale of the lab's text and controls, e.g. 1.5 on a projector.\n")
file(WRITE "${MAN_PAGE}" "${page}")

# ---- the bash completion -------------------------------------------------------------------------
# For one parsed help: its options, those that take a value, and a case arm per option with choices.
function(completion_words prefix words_var valued_var choices_arms_var)
  set(words "")
  set(valued "")
  set(arms "")
  if(${prefix}_Options_COUNT)
    math(EXPR last "${${prefix}_Options_COUNT} - 1")
    foreach(i RANGE ${last})
      option_parts("${${prefix}_Options_${i}_SPEC}" names takes_value choices)
      list(APPEND words ${names})
      if(takes_value)
        list(APPEND valued ${names})
      endif()
      if(choices)
        list(JOIN names "|" pattern)
        string(APPEND arms "        ${pattern}) COMPREPLY=($(compgen -W \"${choices}\" -- \"$cur\")); return ;;\n")
      endif()
    endforeach()
  endif()
  list(JOIN words " " words)
  set(${words_var} "${words}" PARENT_SCOPE)
  set(${valued_var} "${valued}" PARENT_SCOPE)
  set(${choices_arms_var} "${arms}" PARENT_SCOPE)
endfunction()

list(JOIN subcommands " " subcommand_words)
list(JOIN subcommands "|" subcommand_pattern)
completion_words(ROOT root_words root_valued root_arms)
set(option_cases "")
set(choice_cases "${root_arms}")
set(valued_patterns "")
list(APPEND valued_patterns ${root_valued})
foreach(command IN LISTS subcommands)
  completion_words(SUB_${command} words valued arms)
  string(APPEND option_cases "        ${command}) options=\"${words}\" ;;\n")
  string(APPEND choice_cases "${arms}")
  list(APPEND valued_patterns ${valued})
endforeach()
list(REMOVE_DUPLICATES valued_patterns)
list(REMOVE_ITEM valued_patterns --json --csv --png)
list(JOIN valued_patterns "|" valued_pattern)
if(valued_pattern STREQUAL "")
  set(valued_pattern "--no-option-takes-a-value")
endif()

file(WRITE "${COMPLETION}" "# bash completion for radiant. Generated at build time by packaging/GenerateFromHelp.cmake
# from `radiant --help` and each subcommand's --help; do not edit.
_radiant() {
    local cur prev command=\"\" options word
    COMPREPLY=()
    cur=\"\${COMP_WORDS[COMP_CWORD]}\"
    prev=\"\${COMP_WORDS[COMP_CWORD-1]}\"
    for word in \"\${COMP_WORDS[@]:1:COMP_CWORD-1}\"; do
        case \"$word\" in ${subcommand_pattern}) command=\"$word\"; break ;; esac
    done
    case \"$prev\" in
${choice_cases}        --json|--csv|--png) COMPREPLY=($(compgen -f -- \"$cur\")); compopt -o filenames 2>/dev/null; return ;;
        ${valued_pattern}) return ;;
    esac
    case \"$command\" in
${option_cases}        *) options=\"${root_words}\" ;;
    esac
    if [[ \"$cur\" == -* ]]; then
        COMPREPLY=($(compgen -W \"$options\" -- \"$cur\"))
        return
    fi
    # A scene: a built-in name (the .gltf files the program reads, found as it finds them), a glTF
    # file, or at the top level a subcommand.
    local program assets names=\"\"
    program=\"$(type -P \"\${COMP_WORDS[0]}\" 2>/dev/null)\"
    assets=\"\${program%/*}/../share/radiant/assets\"
    [[ -d \"\${program%/*}/assets\" ]] && assets=\"\${program%/*}/assets\"
    if [[ -d \"$assets\" ]]; then
        for word in \"$assets\"/*.gltf; do [[ -e \"$word\" ]] && word=\"\${word##*/}\" && names+=\" \${word%.gltf}\"; done
    fi
    [[ -z \"$command\" ]] && names+=\" ${subcommand_words}\"
    [[ \"$command\" == bench ]] && names=\"\"
    COMPREPLY=($(compgen -W \"$names\" -- \"$cur\"))
    local IFS=$'\\n'
    COMPREPLY+=($(compgen -f -X '!*.@(gltf|glb)' -- \"$cur\") $(compgen -d -- \"$cur\"))
    compopt -o filenames 2>/dev/null
}
complete -F _radiant radiant
")
