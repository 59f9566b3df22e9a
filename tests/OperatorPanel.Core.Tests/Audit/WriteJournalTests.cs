using System.Diagnostics;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Audit;
using OperatorPanel.TestKit;

namespace OperatorPanel.Core.Tests.Audit;

public sealed class WriteJournalTests : IDisposable
{
    private static readonly DateTimeOffset At = new(2026, 11, 27, 16, 38, 2, TimeSpan.Zero);
    private readonly string _folder = Path.Combine(Path.GetTempPath(), "opanel-journal-" + Guid.NewGuid().ToString("N"));
    private readonly ManualTimeProvider _clock = new(At);

    public void Dispose()
    {
        if (Directory.Exists(_folder))
        {
            Directory.Delete(_folder, recursive: true);
        }
    }

    [Fact]
    public async Task RecordAsync_Intent_IsOneJsonLineWithUserPortStationValuesAndProcess()
    {
        var journal = WriteJournal.In(_folder, _clock);

        (await journal.RecordAsync(Intent("COM3"), default)).Should().BeNull();

        var line = File.ReadAllText(journal.Path);
        line.Should().EndWith("\n").And.Contain("\"step\":\"intent\"").And.Contain("\"port\":\"COM3\"").And.Contain("\"station\":2")
            .And.Contain("\"target\":\"VD100\"").And.Contain("\"old\":\"16#00000000\"").And.Contain("\"new\":\"16#000003E7\"")
            .And.Contain($"\"pid\":{Environment.ProcessId}");
    }

    [Fact]
    public void CutShort_IntentOfAnEndedProgramWithoutOutcome_IsFoundOnItsPortOnly()
    {
        var journal = WriteJournal.In(_folder, _clock);
        var ended = EndedProcess();
        var cut = Intent("/dev/ttyUSB0");
        var done = Intent("/dev/ttyUSB0");
        Directory.CreateDirectory(_folder);
        File.WriteAllLines(journal.Path, [
            new JournalLine(cut, ended.Id, ended.Started).Format(),
            new JournalLine(done, ended.Id, ended.Started).Format(),
            new JournalLine(done.Then(AuditStep.Outcome, At, "confirmed", null), ended.Id, ended.Started).Format(),
            new JournalLine(Intent("/dev/ttyUSB1"), ended.Id, ended.Started).Format(),
        ]);

        var (intents, problem) = journal.CutShort(port => port == "/dev/ttyUSB0");

        problem.Should().BeNull();
        intents.Should().ContainSingle().Which.Should().Be(cut);
    }

    [Fact]
    public async Task CutShort_IntentOfAProgramStillRunning_IsLeftToIt()
    {
        var journal = WriteJournal.In(_folder, _clock);
        await journal.RecordAsync(Intent("COM3"), default); // this test's own process: running

        journal.CutShort(_ => true).Intents.Should().BeEmpty("its program may have the frame on the wire right now");
    }

    [Fact]
    public async Task RecordAsync_AfterALineTornByAKill_StartsOnANewLineAndTheTornLineIsReported()
    {
        var journal = WriteJournal.In(_folder, _clock);
        Directory.CreateDirectory(_folder);
        File.WriteAllText(journal.Path, "{\"id\":\"torn");

        await journal.RecordAsync(Intent("COM3"), default);

        File.ReadAllLines(journal.Path).Should().HaveCount(2);
        journal.CutShort(_ => true).Problem.Should().Be($"the write journal {journal.Path} has 1 line(s) that are not entries (torn by a kill, or edited); they were skipped");
    }

    [Fact]
    public async Task RecordAsync_AnotherProgramAppending_WaitsItsTurnAndKeepsTheEntry()
    {
        var journal = WriteJournal.In(_folder, _clock);
        Directory.CreateDirectory(_folder);
        var other = new FileStream(journal.Path, FileMode.OpenOrCreate, FileAccess.ReadWrite, FileShare.None);

        var record = journal.RecordAsync(Intent("COM3"), default).AsTask();
        record.IsCompleted.Should().BeFalse("the journal is held by another writer");
        await other.DisposeAsync();
        _clock.Advance(TimeSpan.FromMilliseconds(20));

        (await record.WaitAsync(TimeSpan.FromSeconds(10))).Should().BeNull();
        File.ReadAllLines(journal.Path).Should().ContainSingle();
    }

    [Fact]
    public async Task RecordAsync_FolderIsAFile_SaysWhyInOurWords()
    {
        File.WriteAllText(_folder, "not a folder");
        try
        {
            var error = await WriteJournal.In(_folder, _clock).RecordAsync(Intent("COM3"), default);

            error.Should().StartWith($"the write journal {Path.Combine(_folder, WriteJournal.FileName)} could not be written: ");
        }
        finally
        {
            File.Delete(_folder);
        }
    }

    internal static AuditEntry Intent(string port) =>
        new(Guid.NewGuid(), AuditStep.Intent, AuditAction.Write, At, "root", port, new Station(2), "VD100", null, "16#00000000", "16#000003E7");

    internal static (int Id, DateTimeOffset Started) EndedProcess()
    {
        using var process = Process.Start(new ProcessStartInfo("true") { UseShellExecute = false })!;
        process.WaitForExit();
        return (process.Id, At); // its start time does not matter: no process with its id runs any more
    }
}
