#!/bin/sh
# Instructions per point query (docs/point-query.md): callgrind's count for
# 20 rounds over the benchmark's 4096 points minus its count for none, per
# query. Usage: tools/query_instructions.sh <wtc_count_query> <shape> [set]
set -e
binary=$1
shape=$2
set_name=${3:-mixed}
rounds=20
count() {
  valgrind --tool=callgrind --callgrind-out-file=/dev/null "$binary" "$shape" "$1" "$set_name" 2>&1 |
    awk '/Collected/ {print $4}'
}
none=$(count 0)
some=$(count "$rounds")
echo "$shape/$set_name $(( (some - none) / (rounds * 4096) )) instructions per query ($(( some - none )) for $rounds x 4096)"
