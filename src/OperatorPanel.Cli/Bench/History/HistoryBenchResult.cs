using System.Globalization;

namespace OperatorPanel.Cli.Bench.History;

/// <summary>What recording one stream for <see cref="LineTime"/> cost, and the figures per day it implies.</summary>
/// <param name="Stream">"2000 tags at 1 s", "demo line".</param>
/// <param name="Values">Values recorded.</param>
/// <param name="LineTime">Simulated line time recorded.</param>
/// <param name="Rows">Rows the writer stored (samples, station states, sessions' marks not counted).</param>
/// <param name="Samples">Value rows in the database at the end.</param>
/// <param name="Bytes">The database file at the end (the write-ahead log merged at close).</param>
/// <param name="RecordingCpu">Process CPU time of recording, less that of feeding the same values with nobody listening.</param>
/// <param name="Wall">Wall-clock time of the recorded run.</param>
internal sealed record HistoryBenchResult(string Stream, int Values, TimeSpan LineTime, long Rows, long Samples, long Bytes, TimeSpan RecordingCpu, TimeSpan Wall)
{
    /// <summary>Percent of one core the recording takes while the line runs in real time.</summary>
    public double CorePercent => 100 * Math.Max(0, RecordingCpu.TotalSeconds) / LineTime.TotalSeconds;

    public double MbPerDay => Bytes / 1e6 * (TimeSpan.FromDays(1) / LineTime);

    public double RowsPerSecond => Rows / LineTime.TotalSeconds;

    public double BytesPerRow => Samples == 0 ? 0 : (double)Bytes / Samples;

    public double CpuMicrosecondsPerRow => Rows == 0 ? 0 : RecordingCpu.TotalMilliseconds * 1000 / Rows;

    public string Line() => string.Create(
        CultureInfo.InvariantCulture,
        $"{Stream,-18} {Values,6} values  {LineTime.TotalHours:0.##} h of line in {Wall.TotalSeconds:0.0} s  rows {Rows,9} ({RowsPerSecond:0.0}/s)  "
        + $"db {Bytes / 1e6:0.00} MB ({BytesPerRow:0.0} B/row, {MbPerDay:0.0} MB/day)  cpu {CorePercent:0.00} % of a core ({CpuMicrosecondsPerRow:0.0} us/row)");
}
