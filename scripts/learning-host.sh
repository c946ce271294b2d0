#!/usr/bin/env bash
# K copies of an environment file's world served to one learner over the learning link (Python's robosim.rl starts
# this itself; python/README.md, "Learning controllers"):
#   scripts/learning-host.sh --env FILE.xml [OPTIONS]    (--help lists the options: --worlds K, --sensors, ...)
# Its first line says where it listens; it serves the first learner whose hello carries ROBOSIM_LINK_KEY (if set).
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
robosim_java robosim.rl.LearningHostMain "$@"
