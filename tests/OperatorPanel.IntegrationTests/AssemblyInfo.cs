// Every test here runs in real time over socat ptys with time-outs of a few hundred milliseconds. Run side by side on a
// 2-core machine they stall each other past those time-outs (CI saw a station's 150 ms answer window missed), so the
// classes take turns: the suite is a little slower and its failures mean the link, not the neighbours.
[assembly: CollectionBehavior(DisableTestParallelization = true)]
