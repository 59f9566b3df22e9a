using System.Diagnostics;
using OperatorPanel.Historian.Reading;
using Serilog.Core;

namespace OperatorPanel.Cli.Bench.History;

/// <summary>
/// Runs a stream through the real historian (recorder, writer, SQLite) on a bench clock, as fast as the machine goes, and
/// measures what recording cost: process CPU time less that of feeding the same stream with nobody recording, the rows
/// and the bytes the database took. One batch per second of line time, as the writer stores them.
/// </summary>
internal static class HistoryBench
{
    private static readonly DateTimeOffset Start = new(2024, 1, 15, 6, 0, 0, TimeSpan.Zero);

    public static async Task<HistoryBenchResult> RunAsync(Func<IHistoryStream> create, TimeSpan duration, string folder)
    {
        // A minute of line first, recorded and thrown away: the figures are of a warm process, not of the JIT.
        Feed(create(), TimeSpan.FromMinutes(1));
        await RecordAsync(create(), TimeSpan.FromMinutes(1), folder);
        var feedOnly = Feed(create(), duration);
        return await RecordAsync(create(), duration, folder, feedOnly);
    }

    private static async Task<HistoryBenchResult> RecordAsync(IHistoryStream stream, TimeSpan duration, string folder, TimeSpan feedOnly = default)
    {
        var path = Path.Combine(folder, $"bench-{Guid.NewGuid():N}.history.db");
        var clock = new BenchClock(Start);
        var line = new BenchLineValues();
        var process = Process.GetCurrentProcess();
        var cpu = process.TotalProcessorTime;
        var wall = Stopwatch.StartNew();
        long written;
        await using (var historian = Historian.Historian.Open(path, stream.Project, clock, Logger.None, "bench"))
        {
            using (historian.RecordLine(stream.Project, line, _ => null))
            {
                var nextBatch = TimeSpan.FromSeconds(1);
                for (var elapsed = TimeSpan.Zero; elapsed < duration; elapsed += stream.Step)
                {
                    clock.MoveTo(Start + elapsed);
                    stream.Publish(line, elapsed, clock.GetUtcNow());
                    if (elapsed >= nextBatch)
                    {
                        await historian.FlushAsync();
                        nextBatch += TimeSpan.FromSeconds(1);
                    }
                }

                clock.MoveTo(Start + duration);
                await historian.FlushAsync();
            }

            written = historian.Written;
        }

        wall.Stop();
        process.Refresh();
        var recording = process.TotalProcessorTime - cpu - feedOnly;
        var figures = new HistoryReader(path).Figures();
        var result = new HistoryBenchResult(stream.Name, stream.Project.Stations.Sum(s => s.Inputs.Length + s.Outputs.Length + s.Tags.Length), duration, written, figures.Samples, figures.Bytes, recording, wall.Elapsed);
        File.Delete(path);
        return result;
    }

    /// <summary>The writer alone: <paramref name="rows"/> rows in batches of <paramref name="batch"/>, rows stored per second of wall time.</summary>
    public static async Task<double> InsertRateAsync(int rows, int batch, string folder)
    {
        var stream = new SyntheticTagStream(batch, Core.Projects.HistorySettings.Default with { DeadbandPercent = 0 });
        var path = Path.Combine(folder, $"insert-{Guid.NewGuid():N}.history.db");
        var clock = new BenchClock(Start);
        var line = new BenchLineValues();
        var wall = new Stopwatch();
        await using (var historian = Historian.Historian.Open(path, stream.Project, clock, Logger.None, "bench"))
        {
            using (historian.RecordLine(stream.Project, line, _ => null))
            {
                await historian.FlushAsync();
                var before = historian.Written;
                for (var second = 1; second <= rows / batch; second++)
                {
                    clock.MoveTo(Start + TimeSpan.FromSeconds(second));
                    stream.Publish(line, TimeSpan.FromSeconds(second), clock.GetUtcNow());
                    wall.Start();
                    await historian.FlushAsync();
                    wall.Stop();
                }

                rows = (int)(historian.Written - before);
            }
        }

        File.Delete(path);
        return rows / wall.Elapsed.TotalSeconds;
    }

    /// <summary>CPU time of publishing the stream with nobody listening: the part of the cost that is the bench's own.</summary>
    private static TimeSpan Feed(IHistoryStream stream, TimeSpan duration)
    {
        var line = new BenchLineValues();
        var process = Process.GetCurrentProcess();
        var cpu = process.TotalProcessorTime;
        for (var elapsed = TimeSpan.Zero; elapsed < duration; elapsed += stream.Step)
        {
            stream.Publish(line, elapsed, Start + elapsed);
        }

        process.Refresh();
        return process.TotalProcessorTime - cpu;
    }
}
