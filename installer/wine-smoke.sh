#!/usr/bin/env bash
# The installed panel, end to end, under Wine: installer/wine-smoke.sh [MSI]
#
# In a throwaway Wine prefix under Xvfb: installs the MSI silently (building it with build.sh when none is given),
# checks the installed files, registry, shortcut and file association, starts the installed panel with --demo and
# waits until its log says it showed a live value change, screenshots it, opens the project wizard and Generate PLC
# code and screenshots them, floats a pane, closes the panel with the pane floating, starts it again and sees the
# window and the floating pane, closes the floating pane with its own close button, starts it again with its Trends
# pane in front and screenshots a live demo trend drawn from the demo's history, opens a project the way a
# double-click does (ShellExecute through the .opproj association) over a corrupt layout file, upgrades to a build
# with a higher version, checks that the older MSI is then refused, uninstalls, and checks that nothing of the panel is
# left while the user's project and logs are. At every step the panel's log must hold no WPF binding error (the panel
# routes WPF's binding trace into it) and no unhandled error, and no unexpected-error dialog may be open. Screenshots
# and logs go to artifacts/wine-smoke/. Exits non-zero naming the failed step.
#
# Test-environment settings, never shipped: a font named "Arial" (Liberation Sans renamed; WPF fails fast without
# one, dotnet/wpf#4464), DOTNET_EnableWriteXorExecute=0 (Wine 8 otherwise crashes the CLR within ~25 s), WPF's
# software renderer (Xvfb has no GPU), no crash debugger and no desktop-menu builder.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
started=$(date +%s)
step="setup"
art="$root/artifacts/wine-smoke"
work=""
xvfb_pid=""
app_pid=""
logs=""

say() { echo "== [$(($(date +%s) - started)) s] $*"; }
begin() { step=$1; say "$1"; }
fail() {
  echo "wine-smoke.sh: FAILED at step '$step': $*" >&2
  exit 1
}
trap 'fail "command failed (exit $?): $BASH_COMMAND"' ERR

# Bounded wait: until COMMAND succeeds, at most SECONDS seconds, polling every second.
wait_for() {
  local seconds=$1
  shift
  local deadline=$(($(date +%s) + seconds))
  until "$@"; do
    [ "$(date +%s)" -lt "$deadline" ] || return 1
    sleep 1
  done
}

# ---- tools -------------------------------------------------------------------------------------------------------
need_install=""
for tool in wine Xvfb xdotool msiinfo wixl /usr/bin/import /usr/bin/convert; do
  command -v "$tool" >/dev/null 2>&1 || need_install=yes
done
/usr/bin/python3 -c 'import fontTools' 2>/dev/null || need_install=yes
[ -f /usr/share/fonts/truetype/liberation2/LiberationSans-Regular.ttf ] || need_install=yes
if [ -n "$need_install" ]; then
  begin "install Wine, Xvfb and helpers"
  SUDO=""
  if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
  $SUDO apt-get update -qq
  $SUDO env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq -o DPkg::Lock::Timeout=600 --no-install-recommends \
    wine wine64 xvfb fonts-liberation2 python3-fonttools imagemagick xdotool msitools wixl >/dev/null
fi

# ---- the two MSIs (before any Wine setting touches HOME) -------------------------------------------------------
msi=${1:-}
if [ -z "$msi" ]; then
  begin "build the MSI"
  bash installer/build.sh
  version=$(sed -n 's|.*<Version>\(.*\)</Version>.*|\1|p' Directory.Build.props | head -n 1)
  msi="$root/artifacts/installer/OperatorPanel-$version-x64.msi"
fi
[ -f "$msi" ] || fail "no MSI at '$msi'"
msi=$(cd "$(dirname "$msi")" && pwd)/$(basename "$msi")
msi_property() { msiinfo export "$1" Property | tr -d '\r' | awk -F '\t' -v p="$2" '$1 == p { print $2 }'; }
msi_files() { msiinfo export "$1" File | tail -n +4 | wc -l; }
version=$(msi_property "$msi" ProductVersion)
product_code=$(msi_property "$msi" ProductCode)
IFS=. read -r major minor patch <<<"$version"
next="$major.$minor.$((patch + 1))"

rm -rf "$art"
mkdir -p "$art"
work=$(mktemp -d /tmp/opanel-wine-smoke.XXXXXX)

cleanup() {
  local status=$?
  trap - ERR
  if [ -n "$work" ] && [ -d "$work/prefix" ]; then
    cp "$work"/*.log "$art/" 2>/dev/null || true
    [ -z "$logs" ] || cp "$logs"/*.log "$art/" 2>/dev/null || true
    # Everything this script started in its own prefix, ended by that prefix's server; then the PIDs it started.
    timeout 30 wineserver -k 2>/dev/null || true
  fi
  for pid in $app_pid $xvfb_pid; do
    kill "$pid" 2>/dev/null || true
  done
  [ -n "$work" ] && rm -rf "$work"
  if [ "$status" -eq 0 ]; then
    echo "wine-smoke.sh: passed in $(($(date +%s) - started)) s; screenshots and logs in $art"
  else
    echo "wine-smoke.sh: failed at step '$step' after $(($(date +%s) - started)) s; screenshots and logs in $art" >&2
  fi
  exit "$status"
}
trap cleanup EXIT

begin "build the upgrade MSI ($next)"
bash installer/build.sh --version "$next" --out "$work/upgrade"
next_msi="$work/upgrade/OperatorPanel-$next-x64.msi"

# ---- Xvfb and the prefix -----------------------------------------------------------------------------------------
begin "start Xvfb"
display=""
for n in $(seq 90 150); do
  if [ ! -e "/tmp/.X11-unix/X$n" ] && [ ! -e "/tmp/.X$n-lock" ]; then display=$n; break; fi
done
[ -n "$display" ] || fail "no free X display number in 90-150"
Xvfb ":$display" -screen 0 1280x800x24 -nolisten tcp >"$work/xvfb.log" 2>&1 &
xvfb_pid=$!
wait_for 30 test -e "/tmp/.X11-unix/X$display" || fail "Xvfb :$display did not come up ($(cat "$work/xvfb.log"))"

export DISPLAY=":$display" WINEPREFIX="$work/prefix" WINEARCH=win64 WINEDEBUG=-all HOME="$work/home"
export DOTNET_EnableWriteXorExecute=0
# No crash debugger (it would hold a crashed panel open) and no desktop entries written outside the prefix.
export WINEDLLOVERRIDES="winedbg.exe=d;winemenubuilder.exe=d"
mkdir -p "$HOME"
w() { timeout "$1" wine "${@:2}"; }
settle() { timeout 60 wineserver -w || fail "Wine did not settle within 60 s"; }

begin "create the Wine prefix"
# mscoree/mshtml off for the first boot only: no offer to download Wine Mono or Gecko (the panel brings its own .NET).
WINEDLLOVERRIDES="$WINEDLLOVERRIDES;mscoree,mshtml=" timeout 300 wineboot -i >"$work/wineboot.log" 2>&1 || fail "wineboot failed ($(tail -3 "$work/wineboot.log"))"
settle
profile=$(w 60 cmd /c 'echo %USERPROFILE%' | tr -d '\r')
profile_unix=$(winepath -u "$profile")
logs="$profile_unix/AppData/Local/OperatorPanel/logs"
pf="$WINEPREFIX/drive_c/Program Files/Operator Panel"

begin "test fonts and settings in the prefix"
fonts="$WINEPREFIX/drive_c/windows/Fonts"
liberation=/usr/share/fonts/truetype/liberation2
{
  printf 'REGEDIT4\r\n\r\n[HKEY_LOCAL_MACHINE\\Software\\Microsoft\\Windows NT\\CurrentVersion\\Fonts]\r\n'
  for entry in Regular:arial Bold:arialbd Italic:ariali BoldItalic:arialbi; do
    style=${entry%%:*}
    file=${entry##*:}
    full=$(/usr/bin/python3 installer/wine-test-font.py "$liberation/LiberationSans-$style.ttf" "$fonts/$file.ttf" Arial "${style/BoldItalic/Bold Italic}")
    printf '"%s (TrueType)"="%s.ttf"\r\n' "$full" "$file"
  done
  printf '\r\n[HKEY_CURRENT_USER\\Software\\Microsoft\\Avalon.Graphics]\r\n"DisableHWAcceleration"=dword:00000001\r\n'
  printf '\r\n[-HKEY_LOCAL_MACHINE\\Software\\Microsoft\\Windows NT\\CurrentVersion\\AeDebug]\r\n'
} >"$work/test-settings.reg"
w 60 regedit /S "$(winepath -w "$work/test-settings.reg")"
settle
w 30 reg query 'HKLM\Software\Microsoft\Windows NT\CurrentVersion\Fonts' /v 'Arial (TrueType)' >/dev/null || fail "the test font is not registered"

# ---- install -----------------------------------------------------------------------------------------------------
msiexec() {
  local log=$1
  shift
  local rc=0
  timeout 600 wine msiexec "$@" /qn /l*v "$(winepath -w "$work")\\$log" || rc=$?
  settle
  return $rc
}
# One value of a registry key ($2 empty: the default value); empty when there is none.
reg_value() {
  local which=(/ve)
  [ -z "${2:-}" ] || which=(/v "$2")
  { w 30 reg query "$1" "${which[@]}" 2>/dev/null || true; } | tr -d '\r' | awk -F '    ' 'NF >= 4 { print $4 }' | head -n 1
}
uninstall_key() { echo "HKLM\\Software\\Microsoft\\Windows\\CurrentVersion\\Uninstall\\$1"; }
start_menu_link() { sed -n 's/^Property(S): ProgramMenuFolder = \(.*\)$/\1/p' "$work/$1" | tr -d '\r' | head -n 1; }

begin "install $version silently"
msiexec install.log /i "$(winepath -w "$msi")" || fail "msiexec /i exited $? (log: install.log)"

begin "check the installed files"
[ -f "$pf/OperatorPanel.exe" ] || fail "no OperatorPanel.exe in $pf"
[ -f "$pf/samples/bottling-line.opproj" ] || fail "the demo sample project is missing"
installed=$(find "$pf" -type f | wc -l)
[ "$installed" -eq "$(msi_files "$msi")" ] || fail "$installed files installed, the MSI holds $(msi_files "$msi")"

begin "check registry, shortcut and association"
[ "$(reg_value "$(uninstall_key "$product_code")" DisplayVersion)" = "$version" ] ||
  fail "no per-machine Add/Remove Programs entry for $version under $(uninstall_key "$product_code")"
[ "$(reg_value 'HKLM\Software\Classes\.opproj')" = "OperatorPanel.Project" ] || fail ".opproj is not associated with OperatorPanel.Project (per machine)"
open_command=$(reg_value 'HKCR\OperatorPanel.Project\shell\open\command')
[ "$open_command" = '"C:\Program Files\Operator Panel\OperatorPanel.exe" "%1"' ] || fail "open command is '$open_command'"
menu=$(winepath -u "$(start_menu_link install.log)")
shortcut="$menu/Operator Panel.lnk"
[ -f "$shortcut" ] || fail "no Start-menu shortcut at $shortcut"
grep -aq 'OperatorPanel.exe' "$shortcut" || fail "the Start-menu shortcut does not point at OperatorPanel.exe"

# ---- run the installed panel ---------------------------------------------------------------------------------------
log_has() { grep -qsF "$1" "$logs"/*.log; }
log_count() { cat "$logs"/*.log 2>/dev/null | grep -cF "$1" || true; }
log_count_above() { [ "$(log_count "$1")" -gt "$2" ]; }
app_alive() { [ -n "$app_pid" ] && kill -0 "$app_pid" 2>/dev/null; }
screenshot() { /usr/bin/import -display "$DISPLAY" -window root "$1"; }
colours() { /usr/bin/convert "$1" -format %k info:; }
# Pictures every 3 s until three in a row differ from one another (something on screen moves), at most 90 s; the last
# is kept as $1. Fails naming $2 (what should have moved) when nothing changed, or when the picture is nearly blank.
screenshot_moving() {
  local shot=$1 what=$2 changes=0
  screenshot "$work/a.png"
  for _ in $(seq 1 30); do
    sleep 3
    screenshot "$work/b.png"
    if cmp -s "$work/a.png" "$work/b.png"; then changes=0; else changes=$((changes + 1)); fi
    mv "$work/b.png" "$work/a.png"
    [ "$changes" -lt 2 ] || break
  done
  cp "$work/a.png" "$shot"
  [ "$changes" -ge 2 ] || fail "$what did not change for 90 s after the log showed it live (see $shot)"
  [ "$(colours "$shot")" -gt 100 ] || fail "the screenshot of $what is nearly blank ($(colours "$shot") colours)"
}
# A panel window is up when Wine has mapped a top-level window whose title names the panel.
window_titled() { xdotool search --onlyvisible --name "$1" >/dev/null 2>&1; }
# Every step ends with the panel healthy: no binding WPF could not resolve, no error the panel did not expect.
panel_clean() {
  local bindings
  bindings=$(grep -hsF "WPF binding error" "$logs"/*.log | head -3 || true)
  [ -z "$bindings" ] || fail "the panel's log has WPF binding errors: $bindings"
  ! log_has "Unhandled error in the panel" || fail "the panel logged an unhandled error: $(grep -hF -A2 'Unhandled error in the panel' "$logs"/*.log | head -3)"
  ! log_has "The panel could not start" || fail "the panel could not start: $(grep -hF -A2 'The panel could not start' "$logs"/*.log | head -3)"
  ! window_titled "unexpected error" || fail "an unexpected-error dialog is open"
}
window_of() { xdotool search --onlyvisible --name "$1" 2>/dev/null | head -n 1; }
# Keys to one window. Xvfb has no window manager and Wine gives keys to the window it holds active: with a floating
# pane open that is the pane's window, whatever X focus says. activate_at clicks a harmless spot of a window first (a
# click makes it Wine's active window); keys_to then sends the keys to the window itself.
activate_at() {
  xdotool mousemove "$1" "$2" click 1
  sleep 1
}
keys_to() {
  local id
  id=$(window_of "$1")
  [ -n "$id" ] || fail "no window titled '$1' to type into"
  xdotool windowfocus "$id" 2>/dev/null || true
  sleep 1
  xdotool key --window "$id" --delay 150 "${@:2}" 2>/dev/null
}
window_gone() { ! window_titled "$1"; }
close_panel() {
  local closed_before
  closed_before=$(log_count "Operator Panel closed")
  # WM_CLOSE to the panel's windows, as the window's close button sends: the panel shuts down the way a user closes it.
  w 30 taskkill /im OperatorPanel.exe >/dev/null || fail "taskkill could not reach the panel"
  wait_for 90 log_count_above "Operator Panel closed" "$closed_before" || fail "the panel did not close within 90 s"
  settle
}

begin "start the installed panel with --demo"
wine 'C:\Program Files\Operator Panel\OperatorPanel.exe' --demo >"$work/panel-demo.out" 2>&1 &
app_pid=$!
wait_for 180 log_has "Operator Panel $version.0 started" || fail "no start in the log within 180 s ($(tail -5 "$work/panel-demo.out"))"

begin "wait for live values"
wait_for 240 log_has "Live values shown" || fail "the panel showed no changing value within 240 s (app alive: $(app_alive && echo yes || echo no); $(tail -5 "$work/panel-demo.out"))"
grep -h -m 1 -F "Live values shown" "$logs"/*.log

begin "screenshot the live demo"
# The log line is written on the UI thread; the picture reaches the X server later: wait for the values to move on screen.
screenshot_moving "$art/panel-demo.png" "the screen"
main_title='Bottling line 1 \(demo\) - Operator Panel'
window_titled "$main_title" || fail "no window titled 'Bottling line 1 (demo) - Operator Panel'"
panel_clean

begin "the project wizard (File > New)"
keys_to "$main_title" ctrl+n
wait_for 30 window_titled '^Project wizard$' || fail "Ctrl+N opened no window titled 'Project wizard'"
sleep 3
screenshot "$art/wizard-cpu.png"
keys_to '^Project wizard$' alt+n
sleep 3
screenshot "$art/wizard-io.png"
keys_to '^Project wizard$' alt+n alt+n alt+n
sleep 3
screenshot "$art/wizard-link.png"
keys_to '^Project wizard$' Escape
wait_for 30 window_gone '^Project wizard$' || fail "Esc did not close the wizard"
panel_clean

begin "Generate PLC code"
keys_to "$main_title" alt+f g
wait_for 30 window_titled '^Generate PLC code$' || fail "File > Generate PLC code opened no window titled 'Generate PLC code'"
keys_to '^Generate PLC code$' alt+g
sleep 5
screenshot "$art/generate.png"
keys_to '^Generate PLC code$' Escape
wait_for 30 window_gone '^Generate PLC code$' || fail "Esc did not close Generate PLC code"
panel_clean

begin "float a pane"
# The Inputs pane's tab sits at the bottom left of the 1280x800 window (default layout); its float button is the
# first icon after the title. A new top-level window titled Inputs proves the click floated it.
xdotool mousemove 62 731 click 1
if ! wait_for 30 window_titled '^Inputs$'; then
  screenshot "$art/float-missed.png"
  fail "clicking the Inputs pane's float button (62,731) opened no window titled Inputs (see $art/float-missed.png)"
fi
sleep 2
screenshot "$art/pane-floating.png"
panel_clean

begin "close the panel with the pane floating"
closed_before=$(log_count "Operator Panel closed")
# The main window's close (Alt+F4 as its close button), not taskkill: taskkill closes every window of the process,
# the floating pane's first, and that hides the pane before the layout is saved. The status bar is the harmless spot.
activate_at 640 772
keys_to "$main_title" alt+F4
wait_for 90 log_count_above "Operator Panel closed" "$closed_before" || fail "the panel did not close within 90 s"
settle
wait_for 30 bash -c "! kill -0 $app_pid 2>/dev/null" || fail "the panel process $app_pid is still running after its log said closed"
app_pid=""
layout="$(dirname "$logs")/layout.json"
python3 - "$layout" <<'PY' || fail "layout.json does not keep the Inputs pane floating and shown: $(cat "$layout")"
import json, sys
panes = {p["ContentId"]: p for p in json.load(open(sys.argv[1]))["Panes"]}
sys.exit(0 if panes["Inputs"]["Placement"] == "Floating" and panes["Inputs"]["IsVisible"] else 1)
PY

begin "start again with the pane floating"
started_before=$(log_count "Operator Panel $version.0 started")
wine 'C:\Program Files\Operator Panel\OperatorPanel.exe' --demo >"$work/panel-restart.out" 2>&1 &
app_pid=$!
wait_for 180 log_count_above "Operator Panel $version.0 started" "$started_before" || fail "no second start in the log within 180 s ($(tail -5 "$work/panel-restart.out"))"
wait_for 60 window_titled "$main_title" || fail "the panel started again without its main window"
wait_for 30 window_titled '^Inputs$' || fail "the Inputs pane did not come back floating"
sleep 8
screenshot "$art/panel-restart.png"
[ "$(colours "$art/panel-restart.png")" -gt 100 ] || fail "the screenshot after the restart is nearly blank"
panel_clean

begin "close the floating pane with its own close button"
# The floating pane opens at 120,120, 480x360 (FloatBounds.Default); its lamp list is the harmless spot.
activate_at 450 300
keys_to '^Inputs$' alt+F4
wait_for 30 window_gone '^Inputs$' || fail "the floating Inputs pane did not close"
sleep 2
window_titled "$main_title" || fail "the main window went with the floating pane"
screenshot "$art/pane-closed.png"
panel_clean

begin "close the panel"
close_panel
wait_for 30 bash -c "! kill -0 $app_pid 2>/dev/null" || fail "the panel process $app_pid is still running after its log said closed"
app_pid=""

begin "start the panel again showing its Trends pane"
# The layout the panel saved, changed as a user leaves it: Inputs docked again at the left, the Trends tab in front of
# Memory in the centre (the first tab by order is the one shown), the Alarms pane below it made lower so the trend's
# lanes have room.
python3 - "$layout" <<'PY' || fail "layout.json could not be set to show the Trends pane: $(cat "$layout")"
import json, sys
path = sys.argv[1]
layout = json.load(open(path))
panes = {p["ContentId"]: p for p in layout["Panes"]}
panes["Inputs"].update(IsVisible=True, Placement="Left")
panes["Memory"]["Order"] = 1
panes["Diagnostics"].update(IsVisible=False, Order=2)
panes["Trends"].update(IsVisible=True, Placement="Center", Order=0)
panes["Alarms"]["DockedSize"] = 200
json.dump(layout, open(path, "w"))
PY
trends_before=$(log_count "Trend drawn:")
wine 'C:\Program Files\Operator Panel\OperatorPanel.exe' --demo >"$work/panel-trends.out" 2>&1 &
app_pid=$!
wait_for 240 log_count_above "Trend drawn:" "$trends_before" || fail "the Trends pane drew no live trend within 240 s (app alive: $(app_alive && echo yes || echo no); $(tail -5 "$work/panel-trends.out"))"
grep -h -F "Trend drawn:" "$logs"/*.log | tail -n 1

begin "screenshot the live trend"
# Redrawn every second from the demo's history: wait for the trend to move on screen.
screenshot_moving "$art/trends-demo.png" "the Trends pane"
ls "$profile_unix/AppData/Local/OperatorPanel/history/"*-demo.history.db >/dev/null 2>&1 || fail "no demo history database in the user's history folder"
panel_clean
close_panel
wait_for 30 bash -c "! kill -0 $app_pid 2>/dev/null" || fail "the panel process $app_pid is still running after its log said closed"
app_pid=""

begin "open a project the way a double-click does, over a corrupt layout file"
# A layout that cannot be restored costs the operator the layout, never the panel: default layout and a notice.
printf '{ "Panes": [ { "ContentId": ' >"$layout"
project_unix="$profile_unix/Documents/Smoke line.opproj"
mkdir -p "$(dirname "$project_unix")"
sed 's/"name": "Bottling line 1"/"name": "Smoke line"/' samples/bottling-line.opproj >"$project_unix"
project_win=$(winepath -w "$project_unix")
# start.exe opens a document through ShellExecute: the .opproj association and its open verb, as Explorer does.
wine start /unix "$project_unix" >"$work/panel-project.out" 2>&1 &
app_pid=$!
wait_for 180 log_has "Opened $project_win from the command line: Smoke line" || fail "the log does not say the panel opened $project_win ($(tail -5 "$work/panel-project.out"))"
wait_for 60 window_titled "Smoke line - Operator Panel" || fail "no window titled 'Smoke line - Operator Panel'"
log_has "Window layout not restored" || fail "the corrupt layout file was not reported in the log"
sleep 5
screenshot "$art/panel-project.png"
panel_clean
close_panel
app_pid=""

begin "upgrade to $next"
msiexec upgrade.log /i "$(winepath -w "$next_msi")" || fail "msiexec /i $next exited $? (log: upgrade.log)"
next_code=$(msi_property "$next_msi" ProductCode)
[ "$(reg_value "$(uninstall_key "$next_code")" DisplayVersion)" = "$next" ] || fail "Add/Remove Programs does not list $next"
! w 30 reg query "$(uninstall_key "$product_code")" >/dev/null 2>&1 || fail "$version is still registered beside $next"
[ "$(strings -el "$pf/OperatorPanel.dll" | grep -cx "$next.0")" -gt 0 ] || fail "the installed OperatorPanel.dll's file version is not $next.0"
[ "$(find "$pf" -type f | wc -l)" -eq "$(msi_files "$next_msi")" ] || fail "file count after the upgrade differs from the $next MSI"

begin "refuse the downgrade to $version"
if msiexec downgrade.log /i "$(winepath -w "$msi")"; then fail "msiexec installed $version over $next"; fi
# The reason: MajorUpgrade's downgrade detection (Wine's msi logs the property, not the condition's message text).
grep -aq "WIX_DOWNGRADE_DETECTED = {" "$work/downgrade.log" || fail "msiexec refused $version, but not as a downgrade (log: downgrade.log)"
[ "$(strings -el "$pf/OperatorPanel.dll" | grep -cx "$next.0")" -gt 0 ] || fail "the refused downgrade changed the installed files"
[ "$(reg_value "$(uninstall_key "$next_code")" DisplayVersion)" = "$next" ] || fail "$next is no longer installed after the refused downgrade"

begin "uninstall"
msiexec uninstall.log /x "$(winepath -w "$next_msi")" || fail "msiexec /x exited $? (log: uninstall.log)"

begin "check that nothing is left but the user's files"
[ ! -e "$pf" ] || fail "$pf is still there: $(find "$pf" | head -5)"
[ ! -e "$shortcut" ] || fail "the Start-menu shortcut is still there"
! w 30 reg query 'HKCR\.opproj' >/dev/null 2>&1 || fail ".opproj is still associated"
! w 30 reg query 'HKCR\OperatorPanel.Project' >/dev/null 2>&1 || fail "the OperatorPanel.Project class is still registered"
! w 30 reg query "$(uninstall_key "$next_code")" >/dev/null 2>&1 || fail "Add/Remove Programs still lists the panel"
[ -f "$project_unix" ] || fail "the uninstall removed the user's project"
ls "$logs"/panel-*.log >/dev/null 2>&1 || fail "the uninstall removed the user's logs"

step="done"
