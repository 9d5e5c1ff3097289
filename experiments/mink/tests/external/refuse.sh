#!/bin/sh
# refuse.sh - an external method that answers with the protocol's error line.
while read -r line; do
	[ "$line" = end ] && echo "error this method takes no such pair"
done
