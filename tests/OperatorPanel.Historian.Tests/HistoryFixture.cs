using System.Collections.Immutable;
using Microsoft.Data.Sqlite;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Projects;
using OperatorPanel.Historian.Reading;
using OperatorPanel.Historian.Recording;
using OperatorPanel.TestKit;

namespace OperatorPanel.Historian.Tests;

/// <summary>
/// A one-station project (an input, a signed word, a float, a hex byte, a counter not recorded) recorded into a database
/// in a temp folder, on a manual clock, from a fake line; everything is deleted on dispose.
/// </summary>
internal sealed class HistoryFixture : IAsyncDisposable
{
    public static readonly Station Station = new(2);
    public static readonly PlcAddress Input = PlcAddress.Parse("I0.0");
    public static readonly PlcAddress Level = PlcAddress.Parse("VW150");
    public static readonly PlcAddress Setpoint = PlcAddress.Parse("VD120");
    public static readonly PlcAddress Fault = PlcAddress.Parse("VB160");
    public static readonly PlcAddress Counter = PlcAddress.Parse("VD100");

    private readonly Dictionary<(Station, PlcAddress), PolledValue> _last = [];

    public HistoryFixture(HistorySettings? settings = null, Action<SqliteConnection>? onOpened = null)
    {
        Directory.CreateDirectory(Folder);
        Project = CreateProject(settings ?? HistorySettings.Default);
        Historian = Historian.Open(DatabasePath, Project, Time, new WriterTuning(TimeSpan.Zero, onOpened));
    }

    public string Folder { get; } = Path.Combine(Path.GetTempPath(), "opanel-history-tests-" + Guid.NewGuid().ToString("N"));

    public string DatabasePath => Path.Combine(Folder, "line.history.db");

    public ManualTimeProvider Time { get; } = new();

    public FakeLineValues Line { get; } = new();

    public PanelProject Project { get; }

    public Historian Historian { get; }

    public Dictionary<Station, StationStatus?> Statuses { get; } = [];

    public static PanelProject CreateProject(HistorySettings settings)
    {
        var project = StarterProject.Create("Line", CpuProfiles.For(CpuModel.Cpu224), Station, "COM3");
        var station = project.Stations[0] with
        {
            Inputs = [new IoSymbol("EStop", Input, string.Empty)],
            Outputs = [],
            Tags =
            [
                new ProjectTag("Level", Level, DisplayFormat.Signed, false, string.Empty),
                new ProjectTag("Setpoint", Setpoint, DisplayFormat.Float, true, string.Empty) { Deadband = 0.25 },
                new ProjectTag("FaultCode", Fault, DisplayFormat.Hex, false, string.Empty),
                new ProjectTag("Bottles", Counter, DisplayFormat.Unsigned, false, string.Empty) { Recorded = false },
            ],
        };
        return project with { Stations = [station], History = settings };
    }

    public IDisposable Record() => Historian.RecordLine(Project, Line, station => Statuses.GetValueOrDefault(station));

    /// <summary>The line reads <paramref name="raw"/> (hex) at <paramref name="address"/> now, with <paramref name="quality"/>.</summary>
    public void Publish(PlcAddress address, string raw, ValueQuality quality = ValueQuality.Good)
    {
        var bytes = raw.Length == 0 ? ImmutableArray<byte>.Empty : [.. Convert.FromHexString(raw)];
        var current = new PolledValue(bytes, Time.GetUtcNow(), quality, quality == ValueQuality.Good ? null : "no answer");
        var previous = _last.GetValueOrDefault((Station, address)) ?? PolledValue.NotRead(Time.GetUtcNow());
        _last[(Station, address)] = current;
        Line.Publish([new ValueChange(Station, address, previous, current)]);
    }

    public async Task<IReadOnlyList<HistorySample>> SamplesAsync(PlcAddress address)
    {
        await Historian.FlushAsync();
        return Historian.Reader.Read([(Station, address)], DateTimeOffset.UnixEpoch, Time.GetUtcNow().AddDays(1))[0].Samples;
    }

    public long Scalar(string sql)
    {
        using var connection = new SqliteConnection($"Data Source={DatabasePath};Mode=ReadOnly;Pooling=False");
        connection.Open();
        using var command = connection.CreateCommand();
        command.CommandText = sql;
        return Convert.ToInt64(command.ExecuteScalar() ?? 0L, System.Globalization.CultureInfo.InvariantCulture);
    }

    public async ValueTask DisposeAsync()
    {
        await Historian.DisposeAsync();
        Directory.Delete(Folder, recursive: true);
    }
}
