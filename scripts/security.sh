#!/usr/bin/env bash
# scripts/security.sh — DDS Security identities for towsim (docs/security.md), with Debian's
# openssl only.
#
#   scripts/security.sh [options] DIR NAME[:BODY,BODY...] ...
#
# Creates DIR (or extends it: existing CAs, identities and the governance are kept) with
#   DIR/identity_ca.pem, identity_ca_key.pem        the identity CA (signs the certificates)
#   DIR/permissions_ca.pem, permissions_ca_key.pem  the permissions CA (signs the documents)
#   DIR/governance.xml, DIR/governance.p7s          config/security/governance.xml, S/MIME-signed
#   DIR/governance_open.xml, governance_open.p7s    with --open-outputs: the node's, admitting
#                                                   participants without a certificate
# and for each NAME an identity DIR/NAME/:
#   cert.pem, key.pem                               EC P-256 key, certificate "CN=NAME,O=towsim"
#   permissions.xml, permissions.p7s                config/security/permissions.xml, signed
# `sim_node` is the node's identity: it publishes every topic except the inputs and subscribes
# to everything. Any other NAME subscribes to everything and publishes the commands of the
# BODYs listed (rt<NS>/<BODY>/command); the pseudo-body `sim_control` grants
# rt<NS>/sim_control. A NAME without bodies reads everything and commands nothing.
# A NAME that already exists is made anew (new key, certificate and permissions).
#
# options:
#   --encrypt       payloads encrypted (AES-GCM) instead of signed (GMAC); rewrites the
#                   governance of an existing DIR (every identity of DIR follows it)
#   --sign          payloads signed (the default of a new DIR); rewrites the governance
#   --open-outputs  the outputs (every topic but the commands and sim_control) unprotected, so
#                   that a node whose scene sets security.open_outputs may let participants
#                   without a certificate read them; rewrites the governance
#   --namespace NS  the ROS 2 namespace the permissions name (default /towsim); fnmatch
#                   wildcards allowed, e.g. '/*' for any namespace (then a controller may
#                   command its body in every system of the domain)
#   --days N        validity of the certificates and permissions made now (default 3650)
#   --expired       the certificates made now expired yesterday (tests of the refusal)
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
templates="$here/../config/security"

usage() {
  sed -n '2,/^set -euo/p' "${BASH_SOURCE[0]}" | sed '$d' | sed 's/^# \{0,1\}//' >&2
  exit 2
}
fail() {
  echo "security.sh: error: $*" >&2
  exit 2
}

protection=""
ns=/towsim
days=3650
expired=0
open_outputs=0
while (($# > 0)); do
  case "$1" in
    --encrypt) protection=ENCRYPT ;;
    --sign) protection=SIGN ;;
    --open-outputs) open_outputs=1 ;;
    --namespace)
      (($# >= 2)) || fail "--namespace needs a value"
      ns="$2"
      shift
      ;;
    --namespace=*) ns="${1#*=}" ;;
    --days)
      (($# >= 2)) || fail "--days needs a value"
      days="$2"
      shift
      ;;
    --days=*) days="${1#*=}" ;;
    --expired) expired=1 ;;
    -h | --help) usage ;;
    --*) fail "unknown option '$1'" ;;
    *) break ;;
  esac
  shift
done
(($# >= 1)) || usage
dir="$1"
shift
[[ "$ns" == /* ]] || fail "--namespace $ns: must start with '/'"
[[ "$days" =~ ^[1-9][0-9]*$ ]] || fail "--days $days: must be an integer >= 1"
[[ "$ns" == / ]] && prefix=rt/ || prefix="rt$ns/"
command -v openssl >/dev/null || fail "openssl not found (apt-get install openssl)"

name_re='^[A-Za-z_][A-Za-z0-9_]*$'
for spec in "$@"; do
  name="${spec%%:*}"
  [[ "$name" =~ $name_re ]] || fail "identity '$spec': the name must match [A-Za-z_][A-Za-z0-9_]*"
  if [[ "$spec" == *:* ]]; then
    IFS=, read -r -a bodies <<<"${spec#*:}"
    for body in "${bodies[@]}"; do
      [[ "$body" =~ $name_re ]] || fail "identity '$spec': body '$body' must match [A-Za-z_][A-Za-z0-9_]*"
    done
    [[ "$name" != sim_node ]] || fail "identity '$spec': sim_node is the node; it takes no bodies"
  fi
done

mkdir -p "$dir"
dir="$(cd "$dir" && pwd)"
quiet() { "$@" >/dev/null 2>"$dir/.openssl.err" || { cat "$dir/.openssl.err" >&2; fail "$1 $2 failed"; }; }

# openssl ca needs a database; it lives in DIR/.ca (serials of the certificates made)
mkdir -p "$dir/.ca"
[[ -f "$dir/.ca/index.txt" ]] || : >"$dir/.ca/index.txt"
[[ -f "$dir/.ca/serial" ]] || echo 1000 >"$dir/.ca/serial"
cat >"$dir/.ca/openssl.cnf" <<EOF
[ ca ]
default_ca = towsim_ca
[ towsim_ca ]
dir = $dir/.ca
database = \$dir/index.txt
serial = \$dir/serial
new_certs_dir = \$dir
default_md = sha256
policy = anything
unique_subject = no
copy_extensions = none
[ anything ]
commonName = supplied
organizationName = optional
[ ca_ext ]
basicConstraints = critical, CA:true
keyUsage = critical, keyCertSign, cRLSign, digitalSignature
subjectKeyIdentifier = hash
[ leaf_ext ]
basicConstraints = CA:false
keyUsage = critical, digitalSignature, keyAgreement
EOF

# date as openssl ca wants it (UTC, YYYYMMDDHHMMSSZ) and as the permissions want it
stamp() { date -u -d "$1" +%Y%m%d%H%M%SZ; }
xml_date() { date -u -d "$1" +%Y-%m-%dT%H:%M:%SZ; }
if ((expired)); then
  start="2 days ago" end="1 day ago"
else
  start="1 hour ago" end="$days days"
fi

make_ca() {  # make_ca FILE_STEM CN
  local stem="$1" cn="$2"
  [[ -f "$dir/$stem.pem" && -f "$dir/${stem}_key.pem" ]] && return
  quiet openssl genpkey -algorithm EC -pkeyopt ec_paramgen_curve:P-256 -out "$dir/${stem}_key.pem"
  quiet openssl req -new -x509 -key "$dir/${stem}_key.pem" -subj "/O=towsim/CN=$cn" -sha256 \
    -days 36500 -config "$dir/.ca/openssl.cnf" -extensions ca_ext -out "$dir/$stem.pem"
}
make_ca identity_ca "towsim identity CA"
make_ca permissions_ca "towsim permissions CA"

sign() {  # sign XML P7S: S/MIME (clear text, detached) by the permissions CA
  quiet openssl smime -sign -text -in "$1" -out "$2" -signer "$dir/permissions_ca.pem" \
    -inkey "$dir/permissions_ca_key.pem"
}

# the governance: kept unless missing or a protection was asked for
governance() {  # governance ALLOW_UNAUTHENTICATED STEM
  local data="${protection:-SIGN}" output_data="${protection:-SIGN}" output_discovery=true
  if ((open_outputs)); then output_data=NONE output_discovery=false; fi
  sed -e "s/@DATA_PROTECTION@/$data/g" -e "s/@OUTPUT_DATA_PROTECTION@/$output_data/g" \
    -e "s/@OUTPUT_DISCOVERY_PROTECTION@/$output_discovery/g" \
    -e "s/@ALLOW_UNAUTHENTICATED@/$1/g" "$templates/governance.xml" >"$dir/$2.xml"
  sign "$dir/$2.xml" "$dir/$2.p7s"
}
if [[ -z "$protection" && $open_outputs == 0 && -f "$dir/governance.p7s" ]]; then
  :
else
  governance false governance
  rm -f "$dir/governance_open.xml" "$dir/governance_open.p7s"
  if ((open_outputs)); then governance true governance_open; fi
fi

topics() {  # topics INDENT TOPIC...
  local indent="$1" t
  shift
  for t in "$@"; do printf '%s<topic>%s</topic>\n' "$indent" "$t"; done
}
domains='        <domains><id_range><min>0</min><max>230</max></id_range></domains>'
rule() {  # rule allow|deny publish|subscribe TOPIC...
  local kind="$1" what="$2"
  shift 2
  printf '      <%s_rule>\n%s\n        <%s>\n          <topics>\n' "$kind" "$domains" "$what"
  topics '            ' "$@"
  printf '          </topics>\n        </%s>\n      </%s_rule>\n' "$what" "$kind"
}

for spec in "$@"; do
  name="${spec%%:*}"
  bodies=()
  [[ "$spec" == *:* ]] && IFS=, read -r -a bodies <<<"${spec#*:}"
  out="$dir/$name"
  mkdir -p "$out"
  quiet openssl genpkey -algorithm EC -pkeyopt ec_paramgen_curve:P-256 -out "$out/key.pem"
  quiet openssl req -new -key "$out/key.pem" -subj "/O=towsim/CN=$name" -out "$out/cert.csr"
  quiet openssl ca -batch -config "$dir/.ca/openssl.cnf" -extensions leaf_ext -notext \
    -cert "$dir/identity_ca.pem" -keyfile "$dir/identity_ca_key.pem" \
    -startdate "$(stamp "$start")" -enddate "$(stamp "$end")" -in "$out/cert.csr" \
    -out "$out/cert.pem"
  rm -f "$out/cert.csr"

  # the rules: the first that names the topic decides (for a topic: in any criterion; for a
  # reader or writer: in its subscribe or publish criterion)
  if [[ "$name" == sim_node ]]; then
    rules="$(rule allow subscribe '*'
             rule deny publish "${prefix}*/command" "${prefix}sim_control"
             rule allow publish '*')"
  else
    publish=()
    for body in "${bodies[@]}"; do
      if [[ "$body" == sim_control ]]; then
        publish+=("${prefix}sim_control")
      else
        publish+=("${prefix}$body/command")
      fi
    done
    # towsim_sertype_probe/*: the process-local probe topic of the recording tools
    # (dds/raw_cdr.h: how Cyclone serializes a type), never seen by another process
    publish+=("towsim_sertype_probe/*")
    # ros_discovery_info: every participant's ROS 2 graph entry (docs/ros2_graph.md)
    publish+=("ros_discovery_info")
    rules="$(rule allow publish "${publish[@]}")"$'\n'
    rules+="$(rule allow subscribe '*')"
  fi
  subject="$(openssl x509 -in "$out/cert.pem" -noout -subject -nameopt RFC2253 | sed 's/^subject=//')"
  awk -v name="$name" -v subject="$subject" -v nb="$(xml_date "$start")" \
      -v na="$(xml_date "$end")" -v rules="$rules" '
    { gsub(/@NAME@/, name); gsub(/@SUBJECT@/, subject); gsub(/@NOT_BEFORE@/, nb);
      gsub(/@NOT_AFTER@/, na) }
    /^@RULES@$/ { print rules; next }
    { print }' "$templates/permissions.xml" >"$out/permissions.xml"
  sign "$out/permissions.xml" "$out/permissions.p7s"
done
rm -f "$dir/.openssl.err"
