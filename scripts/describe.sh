#!/usr/bin/env bash
# What RoboSim knows, from its registries, as `argos3 -q` says it of ARGoS's: the sensors, the robot types and the
# built-in metrics, a line each, or one of them in full by its name (its attributes, its values, its devices, its
# unit):
#   scripts/describe.sh [sensors|robots|metrics|NAME] [--markdown] [--help]
# --markdown writes a list as the Markdown table the READMEs hold (a test holds each README's table to it).
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
robosim_java robosim.runner.DescribeMain "$@"
