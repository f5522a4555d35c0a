"""Formats one `accsim simulate --json` result as a row of the demo table."""
import json
import sys

d = json.load(sys.stdin)


def fmt(v, places):
    return "-" if v is None else f"{v:.{places}f}"


name, ego = sys.argv[1], sys.argv[2]
print(f"{name:<24} {ego:<6} {d['outcome']:<10} {fmt(d['time'], 2):<8} "
      f"{fmt(d['impulse'], 0):<12} {fmt(d['relative_speed'], 2):<10}")
