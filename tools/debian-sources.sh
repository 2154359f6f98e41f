# Fetches Debian source packages into a work folder through a private apt configuration
# (nothing of the host's apt state is touched). Sourced by the scripts that build from
# Debian's sources; they call `debian_sources_setup WORK` once, then `fetch_source`.

# Sets up $work/apt with source lines for Debian unstable, then 13 and 12 for what the
# mirror no longer keeps in unstable; sources are unpacked into $work/src.
debian_sources_setup() {
  work=$1
  mkdir -p "$work/apt/lists/partial" "$work/src" "$work/stamps"
  local mirror suite
  mirror=$(debian_mirror)
  for suite in sid trixie bookworm; do echo "deb-src $mirror $suite main"; done >"$work/apt/sources.list"
  apt_opts=(-o "Dir::Etc::SourceList=$work/apt/sources.list" -o "Dir::Etc::SourceParts=-"
            -o "Dir::State::Lists=$work/apt/lists" -o "APT::Sandbox::User=root" -qq)
  [ -f "$work/stamps/apt" ] || { apt-get "${apt_opts[@]}" update >/dev/null && touch "$work/stamps/apt"; }
}

# Unpacks the newest fetchable source of Debian package $1 whose version starts with $2
# into $work/src/$1 (Debian's patches applied) and notes its version in $work/versions.
fetch_source() {
  local name=$1 wanted=${2:-} version dsc
  [ -f "$work/stamps/source-$name" ] && return 0
  for version in $(apt-cache "${apt_opts[@]}" showsrc "$name" | sed -n 's/^Version: //p' | sort -Vru); do
    case "$version" in "$wanted"*) ;; *) continue ;; esac
    rm -rf "$work/fetch" && mkdir -p "$work/fetch"
    (cd "$work/fetch" && apt-get "${apt_opts[@]}" source --download-only "$name=$version" >/dev/null 2>&1) || continue
    dsc=$(ls "$work"/fetch/*.dsc | head -n1)
    rm -rf "${work:?}/src/$name"
    dpkg-source --no-check -x "$dsc" "$work/src/$name" >/dev/null
    echo "$name $version" >>"$work/versions"
    touch "$work/stamps/source-$name"
    return 0
  done
  die "no source package of $name${wanted:+ $wanted} could be fetched from $(debian_mirror)"
}
