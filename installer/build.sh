#!/usr/bin/env bash
# Builds the Operator Panel MSI: publishes src/OperatorPanel.App for win-x64 and packs it with wixl (msitools).
#
#   installer/build.sh [--version X.Y.Z] [--out DIR]
#
# Writes DIR/OperatorPanel-<version>-x64.msi (DIR defaults to artifacts/installer). The version defaults to
# <Version> in Directory.Build.props, so the program's file versions and the MSI's ProductVersion are the same;
# --version builds another one (wine-smoke.sh builds a higher one to prove the upgrade).
#
# Self-contained, deliberately: a shop PC may have no .NET 10 Desktop Runtime and no internet to fetch it, and a
# framework-dependent panel would then stop at start with a "download .NET" prompt. The MSI carries the runtime
# (about 60 MB instead of about 2 MB); a .NET security patch reaches the PCs with our next MSI.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD

version=$(sed -n 's|.*<Version>\(.*\)</Version>.*|\1|p' Directory.Build.props | head -n 1)
out=artifacts/installer
while [ $# -gt 0 ]; do
  case "$1" in
    --version) version=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    *) echo "build.sh: unknown argument '$1' (use --version X.Y.Z, --out DIR)" >&2; exit 1 ;;
  esac
done
# MSI compares only the first three fields of ProductVersion; each must stay within Windows Installer's limits.
if ! [[ "$version" =~ ^([0-9]{1,3})\.([0-9]{1,3})\.([0-9]{1,5})$ ]] || [ "${BASH_REMATCH[1]}" -gt 255 ] || [ "${BASH_REMATCH[2]}" -gt 255 ] || [ "${BASH_REMATCH[3]}" -gt 65535 ]; then
  echo "build.sh: version '$version' is not X.Y.Z with X, Y <= 255 and Z <= 65535 (Windows Installer ProductVersion)" >&2
  exit 1
fi

if ! command -v wixl >/dev/null 2>&1 || ! command -v msiinfo >/dev/null 2>&1; then
  echo "build.sh: installing wixl and msitools"
  SUDO=""
  if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
  $SUDO apt-get update -qq
  $SUDO env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq -o DPkg::Lock::Timeout=600 wixl msitools >/dev/null
fi

mkdir -p "$out"
out=$(cd "$out" && pwd)
stage="$out/stage-$version"
rm -rf "$stage"
mkdir -p "$stage"

echo "== publish OperatorPanel.App $version for win-x64 (self-contained)"
dotnet publish src/OperatorPanel.App -c Release -r win-x64 --self-contained true --nologo -v minimal \
  -p:Version="$version" -o "$stage/publish"

echo "== wixl"
# wixl stores Source paths as given, so it runs in the stage folder with relative ones.
cd "$stage"
(cd publish && find . -type f | sed 's|^\./||' | sort) | sed 's|^|publish/|' \
  | wixl-heat -p publish/ -x OperatorPanel.exe --var var.SourceDir --component-group AppFiles --directory-ref INSTALLDIR --win64 >files.wxs
msi="$out/OperatorPanel-$version-x64.msi"
wixl -a x64 -D Version="$version" -D SourceDir=publish -D Win64=yes -o "$msi" "$root/installer/OperatorPanel.wxs" files.wxs

echo "== check the MSI"
property() { msiinfo export "$msi" Property | tr -d '\r' | awk -F '\t' -v p="$1" '$1 == p { print $2 }'; }
fail() { echo "build.sh: $msi: $1" >&2; exit 1; }
[ "$(property ProductVersion)" = "$version" ] || fail "ProductVersion is '$(property ProductVersion)', expected $version"
[ "$(property UpgradeCode)" = "{24E5CDF2-9E41-4C6C-9CFA-AC627EF7D5DD}" ] || fail "UpgradeCode changed: '$(property UpgradeCode)' (a new one breaks upgrades)"
[ "$(property ALLUSERS)" = "1" ] || fail "not a per-machine package (ALLUSERS is '$(property ALLUSERS)')"
published=$(find publish -type f | wc -l)
packed=$(msiinfo export "$msi" File | tail -n +4 | wc -l)
[ "$packed" -eq "$published" ] || fail "holds $packed files, the publish folder $published"

cd "$root"
rm -rf "$stage"
echo "build.sh: $msi ($(du -m "$msi" | cut -f1) MB, $packed files)"
