#!/usr/bin/env bash
# Gradescope runs this once when it builds the autograder's image (Ubuntu, as root): a JDK for the grader
# and the submissions' child JVMs, bubblewrap for the sandbox (where the container allows user namespaces;
# otherwise the grader falls back and every results.json says so), prlimit for the limits.
set -euo pipefail
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends openjdk-17-jdk-headless bubblewrap util-linux >/dev/null
chmod +x /autograder/source/run_autograder /autograder/source/raytracer/bin/raytracer
