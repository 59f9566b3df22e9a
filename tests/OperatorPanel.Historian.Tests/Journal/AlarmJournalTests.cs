using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Alarms;
using OperatorPanel.Historian.Journal;
using static OperatorPanel.Historian.Tests.HistoryFixture;

namespace OperatorPanel.Historian.Tests.Journal;

/// <summary>The alarm journal: what it keeps, its search, the restore after a restart, the one-time import of the old file.</summary>
public sealed class AlarmJournalTests
{
    private static readonly PlcAddress Jam = PlcAddress.Parse("M2.1");
    private static readonly PlcAddress Air = PlcAddress.Parse("M2.5");
    private static readonly DateTimeOffset T0 = new(2024, 1, 15, 8, 0, 0, TimeSpan.Zero);

    [Fact]
    public async Task Search_EveryCondition_Filters()
    {
        await using var history = new HistoryFixture();
        var journal = history.Historian.Journal;
        journal.Append(Event(0, Jam, AlarmTransition.Raised, AlarmClass.Fault, "Bottle jam at infeed"), null);
        journal.Append(Event(60, Air, AlarmTransition.Raised, AlarmClass.Warning, "Compressed air pressure low"), null);
        journal.Append(Event(120, Jam, AlarmTransition.Acknowledged, AlarmClass.Fault, "Bottle jam at infeed"), "maria");
        journal.Append(Event(180, Jam, AlarmTransition.Cleared, AlarmClass.Fault, "Bottle jam at infeed", station: 3, name: "Capper"), null);

        (await journal.SearchAsync(JournalFilter.All)).Should().HaveCount(4);
        (await journal.SearchAsync(new JournalFilter(Text: "JAM"))).Should().HaveCount(3);
        (await journal.SearchAsync(new JournalFilter(Text: "capper"))).Should().ContainSingle();
        (await journal.SearchAsync(new JournalFilter(Class: AlarmClass.Warning))).Single().Event.Flag.Should().Be(Air);
        (await journal.SearchAsync(new JournalFilter(Station: new Station(3)))).Single().Event.StationName.Should().Be("Capper");
        (await journal.SearchAsync(new JournalFilter(From: T0.AddSeconds(60), To: T0.AddSeconds(120)))).Select(e => e.Event.At.ToUnixTimeSeconds() - T0.ToUnixTimeSeconds()).Should().Equal(60, 120);
        (await journal.SearchAsync(new JournalFilter(Limit: 2))).Select(e => e.Event.Transition).Should().Equal(AlarmTransition.Acknowledged, AlarmTransition.Cleared);
        (await journal.SearchAsync(new JournalFilter(Text: "%"))).Should().BeEmpty("a LIKE wildcard typed by the operator is a plain character");
    }

    [Fact]
    public async Task Append_Acknowledgement_KeepsWhoAndTheTextAsItWas()
    {
        await using var history = new HistoryFixture();
        history.Historian.Journal.Append(Event(0, Jam, AlarmTransition.Acknowledged, AlarmClass.Fault, "Old text, \"quoted\""), "maria");

        var entry = (await history.Historian.Journal.SearchAsync(JournalFilter.All)).Single();

        entry.User.Should().Be("maria");
        entry.Event.Should().Be(Event(0, Jam, AlarmTransition.Acknowledged, AlarmClass.Fault, "Old text, \"quoted\""));
    }

    [Fact]
    public async Task SinceLastRaise_ReturnsEachAlarmsEntriesFromItsLatestRaise()
    {
        await using var history = new HistoryFixture();
        var journal = history.Historian.Journal;
        journal.Append(Event(0, Jam, AlarmTransition.Raised, AlarmClass.Fault, "jam"), null);
        journal.Append(Event(10, Jam, AlarmTransition.Cleared, AlarmClass.Fault, "jam"), null);
        journal.Append(Event(20, Jam, AlarmTransition.Raised, AlarmClass.Fault, "jam"), null);
        journal.Append(Event(30, Air, AlarmTransition.Raised, AlarmClass.Warning, "air"), null);
        journal.Append(Event(40, Jam, AlarmTransition.Acknowledged, AlarmClass.Fault, "jam"), "maria");

        var events = await journal.SinceLastRaiseAsync();

        events.Select(e => (e.Flag, (e.At - T0).TotalSeconds)).Should().Equal((Jam, 20), (Air, 30), (Jam, 40));
    }

    [Fact]
    public async Task ImportOnce_OldHistoryFile_IsImportedOnlyTheFirstTime()
    {
        await using var history = new HistoryFixture();
        var project = Path.Combine(history.Folder, "line.opproj");
        var file = new AlarmHistoryFile(AlarmHistoryFile.PathFor(project), history.Time);
        File.WriteAllText(file.Path, string.Empty);
        file.TryAppend([Event(0, Jam, AlarmTransition.Raised, AlarmClass.Fault, "jam"), Event(5, Jam, AlarmTransition.Cleared, AlarmClass.Fault, "jam")], out _).Should().BeTrue();

        var first = await history.Historian.Journal.ImportOnceAsync(project, history.Time);
        var second = await history.Historian.Journal.ImportOnceAsync(project, history.Time);

        first.Imported.Should().Be(2);
        second.Imported.Should().Be(0);
        (await history.Historian.Journal.SearchAsync(JournalFilter.All)).Should().HaveCount(2);
        File.Exists(file.Path).Should().BeTrue("the user's file is left where it was");
    }

    private static AlarmEvent Event(int seconds, PlcAddress flag, AlarmTransition transition, AlarmClass alarmClass, string text, int station = 2, string name = "Filler") =>
        new(T0.AddSeconds(seconds), name, new Station(station), flag, transition,
            transition == AlarmTransition.Cleared ? AlarmState.Cleared : AlarmState.ActiveUnacknowledged, alarmClass, text);
}
