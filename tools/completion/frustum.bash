# bash completion for frustum. It reads `frustum --help` and `frustum SUBCOMMAND --help` when
# asked, so subcommands, options and the words of a choice ({text,markdown,json}) are always
# those of the installed binary. Installed as share/bash-completion/completions/frustum.
_frustum() {
  local cur prev words cword
  _init_completion || return
  local i sub="" path=() args=0
  for ((i = 1; i < cword; i++)); do
    case "${words[i]}" in
      -*) ;;
      *) if [[ -z $sub || ($sub == bench && ${#path[@]} == 1) ]]; then
           sub=${words[i]}; path+=("$sub"); args=0
         elif [[ ${words[i - 1]} != -* ]]; then
           args=$((args + 1))  # a positional argument (not an option's value)
         fi ;;
    esac
  done
  local help
  help=$("${words[0]}" "${path[@]}" --help 2>/dev/null) || return
  # The words of a choice option: "--format FORMAT:{text,markdown,json}".
  if [[ $prev == -* ]]; then
    local choices
    choices=$(sed -n "s/^ *\(-[^ ]*,\)\?${prev}[ ,][^{]*{\([^}]*\)}.*/\2/p" <<<"$help" | head -n 1)
    if [[ -n $choices ]]; then
      mapfile -t COMPREPLY < <(compgen -W "${choices//,/ }" -- "$cur")
      return
    fi
    if grep -qE "^ *(-[^ ]*,)?${prev} [A-Z]" <<<"$help"; then
      _filedir
      return
    fi
  fi
  if [[ $cur == -* ]]; then
    mapfile -t COMPREPLY < <(compgen -W "$(grep -oE '^ *(-[a-zA-Z],)?--[a-z-]+' <<<"$help" | tr ',' ' ')" -- "$cur")
    return
  fi
  # The positional argument being typed: its words when it is a choice ("format
  # TEXT:{prairielearn,qti,...}" under "Positionals:"), as `frustum export <TAB>` offers.
  local positional
  positional=$(sed -n '/^Positionals:/,/^[A-Z]/s/^  \([a-z][a-z_-]*\) .*/&/p' <<<"$help" | sed -n "$((args + 1))p")
  if [[ $positional =~ \{([^}]*)\} ]]; then
    mapfile -t COMPREPLY < <(compgen -W "${BASH_REMATCH[1]//,/ }" -- "$cur")
    return
  fi
  # Subcommands are listed under "Subcommands:"; otherwise complete files.
  local subs
  subs=$(sed -n '/^Subcommands:/,/^$/s/^  \([a-z]\+\) .*/\1/p' <<<"$help")
  if [[ -n $subs ]]; then
    mapfile -t COMPREPLY < <(compgen -W "$subs" -- "$cur")
  else
    _filedir
  fi
}
complete -F _frustum frustum
