#!/bin/sh
# hang.sh - an external method that reads its job and never answers.
while read -r line; do :; done
sleep 1000
