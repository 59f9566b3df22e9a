using OperatorPanel.Cli.Commands;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Alarms;
using OperatorPanel.Core.Line;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Transport;
using OperatorPanel.Core.Values;

namespace OperatorPanel.Cli.Watch;

/// <summary>Reads a <see cref="WatchSession"/>'s line (values, station states, link counters) into a <see cref="WatchSnapshot"/>.</summary>
internal static class SnapshotBuilder
{
    public static WatchSnapshot Build(WatchSession session, long cycle, DateTimeOffset time)
    {
        var refresh = session.Project.Refresh;
        var refreshText = refresh.Mode == RefreshMode.Continuous
            ? $"continuous, at least {refresh.MinimumPeriod.TotalMilliseconds:0} ms apart"
            : "triggered, one refresh a second";
        var stations = ProjectBus.Of(session.Project)
            .SelectMany(b => b.Stations.Select(s => Station(s, session, time)))
            .ToList();
        return new WatchSnapshot(session.Project.Name, refreshText, cycle, time, stations);
    }

    private static StationSnapshot Station(ProjectStation station, WatchSession session, DateTimeOffset now)
    {
        var line = session.Line;
        var status = line.StatusOf(station.Address) ?? StationStatus.Initial(station.Address);
        var statistics = line.StatisticsFor(station.Address);
        PolledValue? Value(PlcAddress address) => line.TryGetValue(station.Address, address, out var v) && v.HasValue ? v : null;
        PolledValue? Reading(PlcAddress address) => line.TryGetValue(station.Address, address, out var v) ? v : null;
        return new StationSnapshot(
            station.Name,
            station.Address.Address,
            station.Cpu.DisplayName,
            $"{line.PortOf(station.Address)} {station.Link.LineText}{(station.Link.Protocol == LinkProtocol.Ppi ? " PPI" : "")}",
            status.State.ToString().ToLowerInvariant(),
            LinkFailure.WithoutKind(status.LastError, status.LastErrorKind),
            status.NextTryAt is { } next ? Math.Max(0, (int)Math.Ceiling((next - now).TotalSeconds)) : null,
            session.HandlerCheckOf(station.Address),
            new LinkView(statistics.Requests, statistics.Replies, statistics.Retries, statistics.Timeouts, statistics.RoundTripAverage?.TotalMilliseconds),
            Lamps(station.Inputs, Reading),
            Lamps(station.Outputs, Reading),
            [.. station.Tags.Select(t => Tag(t, Value(t.Address), line, station.Address))],
            Alarms(station, line))
        {
            AlarmsDefined = station.Alarms.Length,
        };
    }

    /// <summary>Active alarms, and every alarm whose flag has no good reading (Core's AlarmFlag: unknown is never "not set").</summary>
    private static List<AlarmRow> Alarms(ProjectStation station, ProjectLine line) =>
        [.. station.Alarms
            .Select(a => (Alarm: a, On: AlarmFlag.Reading(line.TryGetValue(station.Address, a.Flag, out var v) ? v : null)))
            .Where(a => a.On != false)
            .Select(a => new AlarmRow(a.Alarm.Flag.ToString(), a.Alarm.Text, a.Alarm.Class.ToString().ToLowerInvariant(), a.On is null ? AlarmRow.Unknown : AlarmRow.Active))];

    /// <summary>
    /// The lamps of <paramref name="symbols"/> from each bit's reading (null: the line has none). A lamp is lit or dark
    /// only on a good reading: a stale bit (station offline, port gone) or a bad one is <see cref="LampByte.Unknown"/>,
    /// as a bit never read is, since one character cannot say "last known, not current" (JSON keeps the last reading
    /// beside its quality, as a tag's value is kept beside its quality).
    /// </summary>
    internal static List<LampByte> Lamps(IEnumerable<IoSymbol> symbols, Func<PlcAddress, PolledValue?> reading) =>
        [.. symbols
            .GroupBy(s => s.Address.ByteOffset)
            .OrderBy(g => g.Key)
            .Select(g =>
            {
                var bits = g.OrderBy(s => s.Address.Bit).Select(s => Bit(s, reading(s.Address))).ToList();
                var first = g.First().Address;
                var lamps = new char[8];
                for (var bit = 0; bit < 8; bit++)
                {
                    var symbol = g.FirstOrDefault(s => s.Address.Bit == bit);
                    lamps[bit] = symbol is null ? LampByte.Unused : reading(symbol.Address) is { Quality: ValueQuality.Good, AsBit: { } on }
                        ? (on ? LampByte.On : LampByte.Off)
                        : LampByte.Unknown;
                }

                return new LampByte(PlcAddress.ForBytes(first.Area, first.ByteOffset, AccessWidth.Byte).ToString(), new string(lamps), bits);
            })];

    private static LampBit Bit(IoSymbol symbol, PolledValue? reading) =>
        new(symbol.Address.ToString(), symbol.Symbol, reading?.AsBit, QualityOf(reading));

    /// <summary>A reading's quality as watch prints it; no reading at all is "bad" (not usable), as for a tag.</summary>
    private static string QualityOf(PolledValue? reading) => (reading?.Quality ?? ValueQuality.Bad).ToString().ToLowerInvariant();

    private static TagRow Tag(ProjectTag tag, PolledValue? value, ProjectLine line, Station station)
    {
        var quality = QualityOf(line.TryGetValue(station, tag.Address, out var polled) ? polled : null);
        var text = value is null ? "-" : TagValues.Format(tag, value.Raw.AsSpan());
        return new TagRow(tag.Symbol, tag.Address.ToString(), text, quality);
    }
}
