#!/bin/sh
# garbage.sh - an external method whose answer breaks the protocol.
while read -r line; do
	if [ "$line" = end ]; then
		echo "points 2"
		echo "1 2"
		echo "banana"
	fi
done
