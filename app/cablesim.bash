# SPDX-License-Identifier: MIT
# bash completion for cablesim: its commands, each command's options, the values of --standard and
# --only, model and spec files (*.yaml) and folders. Installed as
# share/bash-completion/completions/cablesim.
_cablesim() {
    local cur prev cmd
    cur=${COMP_WORDS[COMP_CWORD]}
    prev=${COMP_WORDS[COMP_CWORD - 1]}
    cmd=${COMP_WORDS[1]:-}
    if [ "$COMP_CWORD" -eq 1 ]; then
        mapfile -t COMPREPLY < <(compgen -W "run check sweep rate validate compare designer list schema --help --version" -- "$cur")
        return
    fi
    case $prev in
    -o | --out | --examples | --resume | --allow-path)
        mapfile -t COMPREPLY < <(compgen -d -- "$cur")
        return
        ;;
    --standard)
        mapfile -t COMPREPLY < <(compgen -W "sd-std-02.01 sd-std-02.01a astm-f2656 nchrp-350 mash" -- "$cur")
        return
        ;;
    --only)
        mapfile -t COMPREPLY < <(compgen -W "crash readings roadside bogie verification convergence sensitivity" -- "$cur")
        return
        ;;
    --level)
        mapfile -t COMPREPLY < <(compgen -W "3 4" -- "$cur")
        return
        ;;
    --set | --dt | --t-end | --occupant-at | --threads | --runs | --seed | --class | --test)
        return
        ;;
    esac
    local opts=""
    case $cmd in
    run) opts="-o --out --force --dt --t-end --set --plots --report --occupant-at --allow-path --help" ;;
    check) opts="--dt --t-end --set --allow-path --help" ;;
    sweep) opts="-o --out --threads --runs --seed --set --t-end --dt --netcdf --allow-path --quiet --force --resume --help" ;;
    rate) opts="--standard --class --level --test --set --allow-path --help" ;;
    validate) opts="-o --out --force --examples --only --report-only --help" ;;
    compare) opts="-o --out --measured --force --help" ;;
    designer) opts="-o --out --force --allow-path --help" ;;
    list | schema) opts="--help" ;;
    *) return ;;
    esac
    if [[ $cur == -* ]]; then
        mapfile -t COMPREPLY < <(compgen -W "$opts" -- "$cur")
    else
        mapfile -t COMPREPLY < <(compgen -f -X '!*.yaml' -- "$cur"; compgen -d -- "$cur")
    fi
}
complete -F _cablesim cablesim
