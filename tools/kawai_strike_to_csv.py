#!/usr/bin/env python3
"""Cuts one strike out of a raw Kawai KG-3C hammer-shank trace (shared/data/kawai-kg3c,
Greg Zweigle, MIT licence) and writes it in the measured-data format (DESIGN.md section 5).

The sensor is not calibrated for these files. The conversion assumes:
  * the reading rises monotonically as the hammer rises (true of the files: rest ~0.21 of full
    scale, string contact ~0.47);
  * rest = the median of the 0.2 s before the strike, the string = the strike's peak;
  * between them, position at the sensor follows the author's hammer calibration points of
    calibration.csv (measured on the two-column file with the same sensor type), normalised;
  * hammer angle = that normalised position x the grand model's blow angle (19.0 deg: a 45 mm
    blow at a 137 mm strike radius), since the sensor sits near the flange.
usage: kawai_strike_to_csv.py RAW CALIBRATION START_S END_S RATE_HZ OUT
"""
import csv
import sys

BLOW_DEG = 19.0


def main():
    raw_path, cal_path, start, end, rate, out = sys.argv[1:7]
    start, end, rate = float(start), float(end), float(rate)
    values = [float(x) / 2**24 for x in open(raw_path).read().split()]
    cal = [(float(r["position_in"]), float(r["normalized_reading"]))
           for r in csv.DictReader(line for line in open(cal_path) if not line.startswith("#"))
           if r["sensor"] == "hammer"]
    full = cal[-1][0]
    i0, i1 = int(start * rate), int(end * rate)
    peak_index = max(range(i0, i1), key=lambda i: values[i])
    before = sorted(values[max(0, peak_index - int(0.3 * rate)):peak_index - int(0.1 * rate)])
    rest, peak = before[len(before) // 2], values[peak_index]

    def position(reading):  # inverse of the calibration curve, linear between its points
        r = (reading - rest) / (peak - rest)
        if r <= 0:
            return r * cal[1][0] / cal[1][1] / full  # below rest: the first segment's slope
        for (p0, r0), (p1, r1) in zip(cal, cal[1:]):
            if r <= r1:
                return (p0 + (p1 - p0) * (r - r0) / (r1 - r0)) / full
        return 1.0 + (r - 1.0) * (cal[-1][0] - cal[-2][0]) / (cal[-1][1] - cal[-2][1]) / full

    with open(out, "w") as f:
        f.write("# action: grand\n")
        f.write("# source: %s samples %d-%d (%g-%g s) of Piano-Data by Greg Zweigle, MIT licence "
                "(see LICENSE-kawai-kg3c)\n" % (raw_path.split("/")[-1], i0, i1, start, end))
        f.write("# calibration: uncalibrated sensor; rest and string peak mapped through the "
                "author's hammer calibration points to 0 and %g deg\n" % BLOW_DEG)
        f.write("time_s,hammer_angle_deg\n")
        for i in range(i0, i1):
            f.write("%.6f,%.4f\n" % ((i - i0) / rate, BLOW_DEG * position(values[i])))


if __name__ == "__main__":
    main()
