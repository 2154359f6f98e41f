#!/usr/bin/env bash
# Creates the project's Python venv (.venv): the pinned dependencies (requirements.txt)
# and the project's own tools as one package (pyproject.toml, installed editable, so
# their commands run the tree's code).
source "$(dirname "$0")/common.sh"

requirements="$PROJECT_ROOT/tools/requirements.txt"
package="$PROJECT_ROOT/tools/pyproject.toml"
venv="$PROJECT_ROOT/.venv"
stamp="$venv/.requirements-$(sha256sum "$requirements" | cut -c1-12)"
if [ ! -f "$stamp" ]; then
  log "creating the Python tools venv in $venv"
  rm -rf "$venv"
  python3 -m venv "$venv"
  "$venv/bin/pip" install -q --disable-pip-version-check -r "$requirements"
  touch "$venv/.gdignore" "$stamp"
fi
package_stamp="$venv/.package-$(sha256sum "$package" | cut -c1-12)"
if [ ! -f "$package_stamp" ]; then
  log "installing the project's Python tools into the venv"
  "$venv/bin/pip" install -q --disable-pip-version-check -e "$PROJECT_ROOT/tools"
  rm -f "$venv"/.package-*
  touch "$package_stamp"
fi
