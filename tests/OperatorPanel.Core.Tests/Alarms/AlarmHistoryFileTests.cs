using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Alarms;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Tests.Projects;
using OperatorPanel.TestKit;

namespace OperatorPanel.Core.Tests.Alarms;

public sealed class AlarmHistoryFileTests : IDisposable
{
    private readonly TempFolder _folder = new();
    private readonly ManualTimeProvider _clock = new();

    public void Dispose() => _folder.Dispose();

    [Fact]
    public void PathFor_ProjectFile_IsBesideItWithTheAlarmSuffix() =>
        AlarmHistoryFile.PathFor(Path.Combine("plant", "line.opproj")).Should().Be(Path.Combine("plant", "line.alarms.jsonl"));

    [Fact]
    public void Load_NoFile_IsEmptyWithoutMessage() =>
        new AlarmHistoryFile(_folder.File("none.alarms.jsonl"), _clock).Load().Should().Be(new AlarmHistoryLoad([], null));

    [Fact]
    public void AppendThenLoad_EveryField_RoundTrips()
    {
        var history = new AlarmHistoryFile(_folder.File("a.alarms.jsonl"), _clock);
        AlarmEvent[] entries =
        [
            Entry(AlarmTransition.Raised, AlarmState.ActiveUnacknowledged, "Überlauf, Tank \"2\"\nbitte prüfen"),
            Entry(AlarmTransition.Acknowledged, AlarmState.ActiveAcknowledged, "x") with { Class = AlarmClass.Information },
        ];

        history.TryAppend(entries, out var error).Should().BeTrue(error);

        history.Load().Events.Should().Equal(entries);
    }

    [Fact]
    public void Load_TornLastLine_DropsItWithMessageAndTruncatesTheFile()
    {
        var path = _folder.File("t.alarms.jsonl");
        var history = new AlarmHistoryFile(path, _clock);
        history.TryAppend([Entry(AlarmTransition.Raised, AlarmState.ActiveUnacknowledged, "Jam")], out _).Should().BeTrue();
        File.AppendAllText(path, "{\"time\":\"2024-01-15T08:0");

        var load = history.Load();

        load.Events.Should().ContainSingle();
        load.Message.Should().Contain("was cut short");
        File.ReadAllText(path).Should().EndWith("}\n");
        history.Load().Message.Should().BeNull();
    }

    [Fact]
    public void Load_NotUtf8_IsSetAside()
    {
        var path = _folder.File("b.alarms.jsonl");
        File.WriteAllBytes(path, [0xFF, 0xFE, 0x00, (byte)'\n']);

        var load = new AlarmHistoryFile(path, _clock).Load();

        load.Events.Should().BeEmpty();
        load.Message.Should().Contain("it is not UTF-8 text");
        File.Exists(path).Should().BeFalse();
    }

    [Theory]
    [InlineData("plain", "plain")]
    [InlineData("a,b", "\"a,b\"")]
    [InlineData("say \"hi\"", "\"say \"\"hi\"\"\"")]
    [InlineData("two\r\nlines", "\"two\r\nlines\"")]
    public void CsvQuote_Field_FollowsRfc4180(string field, string expected) => AlarmCsv.Quote(field).Should().Be(expected);

    private AlarmEvent Entry(AlarmTransition transition, AlarmState state, string text) =>
        new(_clock.GetUtcNow().AddMilliseconds(250), "Filler", new Station(7), PlcAddress.Parse("V100.7"), transition, state, AlarmClass.Fault, text);
}
