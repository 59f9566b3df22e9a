using System.Collections.Immutable;
using System.Globalization;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Projects;

namespace OperatorPanel.Cli.Bench.History;

/// <summary>
/// <see cref="Count"/> analogue tags (signed words VW0, VW2, ... of one CPU 226) read once a second, each a process value
/// with measurement noise: base 1000-20000, a slow swing of 5 % of it over 20 min to 2 h, and noise of up to ±0.2 %
/// every reading, so nearly every tag changes every second. Deterministic: the same figures run after run.
/// </summary>
internal sealed class SyntheticTagStream : IHistoryStream
{
    private static readonly Station Station = new(2);
    private readonly Tag[] _tags;

    public SyntheticTagStream(int count, HistorySettings settings)
    {
        Count = count;
        var random = new Random(22);
        _tags = [.. Enumerable.Range(0, count).Select(i =>
        {
            var level = 1000 + random.NextDouble() * 19000;
            return new Tag(PlcAddress.ForBytes(MemoryArea.V, 2 * i, AccessWidth.Word), level, level * 0.05, TimeSpan.FromMinutes(20 + random.NextDouble() * 100).TotalSeconds, random.NextDouble() * Math.Tau, level * 0.002);
        })];
        var station = StarterProject.Create("bench", CpuProfiles.For(CpuModel.Cpu226), Station, "COM1").Stations[0] with
        {
            Inputs = [],
            Outputs = [],
            Tags = [.. _tags.Select((t, i) => new ProjectTag(string.Create(CultureInfo.InvariantCulture, $"Analog{i}"), t.Address, DisplayFormat.Signed, false, string.Empty))],
        };
        Project = new PanelProject("bench", RefreshSettings.Default, [station]) { History = settings };
    }

    public int Count { get; }

    public string Name => string.Create(CultureInfo.InvariantCulture, $"{Count} tags at 1 s");

    public PanelProject Project { get; }

    public TimeSpan Step => TimeSpan.FromSeconds(1);

    public void Publish(BenchLineValues line, TimeSpan elapsed, DateTimeOffset at)
    {
        var seconds = (long)elapsed.TotalSeconds;
        for (var i = 0; i < _tags.Length; i++)
        {
            var t = _tags[i];
            var value = t.Level + t.Swing * Math.Sin(Math.Tau * seconds / t.PeriodS + t.Phase) + t.Noise * Noise(i, seconds);
            var word = (short)Math.Round(value);
            line.Publish(Station, t.Address, PolledValue.Good(ImmutableArray.Create((byte)(word >> 8), (byte)word), at));
        }
    }

    /// <summary>Uniform in [-1, 1], from a hash of the tag and the second (no state, the same every run).</summary>
    private static double Noise(int tag, long second)
    {
        var x = (ulong)(tag * 0x9E3779B1L) ^ (ulong)(second * 0x85EBCA77L);
        x ^= x >> 33;
        x *= 0xFF51AFD7ED558CCDUL;
        x ^= x >> 33;
        return (x % 2_000_001) / 1_000_000.0 - 1;
    }

    private sealed record Tag(PlcAddress Address, double Level, double Swing, double PeriodS, double Phase, double Noise);
}
