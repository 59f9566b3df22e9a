using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Audit;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Tests.Audit;
using OperatorPanel.Core.Tests.Polling;
using OperatorPanel.Core.Transport;
using OperatorPanel.Core.Writes;

namespace OperatorPanel.Core.Tests.Writes;

/// <summary>A write cut short (its program killed between intent and outcome) is settled at the next start by reading back.</summary>
public sealed class UnfinishedWritesTests : IDisposable
{
    private readonly string _folder = Path.Combine(Path.GetTempPath(), "opanel-unfinished-" + Guid.NewGuid().ToString("N"));
    private readonly PollingTestClock _clock = new();
    private readonly FakePlcLink _link;
    private readonly WriteJournal _journal;

    public UnfinishedWritesTests()
    {
        _link = new FakePlcLink(_clock);
        _journal = WriteJournal.In(_folder, _clock);
    }

    public void Dispose()
    {
        if (Directory.Exists(_folder))
        {
            Directory.Delete(_folder, recursive: true);
        }
    }

    [Theory]
    [InlineData(0x03, 0xE7, UnfinishedWrites.Applied, "the PLC holds the requested 16#000003E7")]
    [InlineData(0x00, 0x00, UnfinishedWrites.NotApplied, "the PLC still holds the old 16#00000000")]
    [InlineData(0x00, 0x05, UnfinishedWrites.Unknown, "the PLC holds 16#00000005, neither the old 16#00000000 nor the requested 16#000003E7: its program may have changed it since")]
    public async Task ResolveAsync_IntentWithoutOutcome_IsReadBackAndRecordedAsResolvedAtStart(byte high, byte low, string outcome, string detail)
    {
        _link.Set(new Station(2), ProtocolArea.V, 100, 0, 0, high, low);
        var cut = WriteCutShort("COM3");

        var (resolved, problem) = await UnfinishedWrites.ResolveAsync(_journal, _link, "COM3", _clock);

        problem.Should().BeNull();
        resolved.Should().ContainSingle();
        resolved[0].Intent.Should().Be(cut);
        resolved[0].Resolution.Should().Be(cut with { Step = AuditStep.ResolvedAtStart, At = PollingTestClock.Start, Outcome = outcome, Detail = detail });
        _journal.CutShort(_ => true).Intents.Should().BeEmpty("the resolution settles it for good");
        _link.Requests.Should().ContainSingle().Which.Should().BeOfType<ReadRequest>("a write cut short is read back, never sent again");
    }

    [Fact]
    public async Task ResolveAsync_AnotherPort_IsLeftForThatPort()
    {
        WriteCutShort("COM4");

        (await UnfinishedWrites.ResolveAsync(_journal, _link, "COM3", _clock)).Resolved.Should().BeEmpty();
        _journal.CutShort(_ => true).Intents.Should().ContainSingle();
    }

    [Fact]
    public async Task ResolveAsync_PortUnavailable_SettlesNothingYet()
    {
        WriteCutShort("COM3");
        _link.Fail(new Station(2), new PlcCommunicationException(PlcErrorKind.PortUnavailable, null, "serial port COM3: open failed"));

        (await UnfinishedWrites.ResolveAsync(_journal, _link, "COM3", _clock)).Resolved.Should().BeEmpty();
        _journal.CutShort(_ => true).Intents.Should().ContainSingle("a later start with the port back settles it");
    }

    [Fact]
    public async Task ResolveAsync_WriteToASimulatedLine_IsUnknownWithoutAnyExchange()
    {
        WriteCutShort("COM3 (demo)");

        var (resolved, _) = await UnfinishedWrites.ResolveAsync(_journal, _link, "/dev/ttyUSB0", _clock);

        resolved.Should().ContainSingle().Which.Resolution.Outcome.Should().Be(UnfinishedWrites.Unknown);
        _link.Requests.Should().BeEmpty();
    }

    [Fact]
    public void Describe_CutShortWrite_SaysWhatWhoWhenAndHowItWasSettled()
    {
        var intent = WriteJournalTests.Intent("COM3") with { Symbol = "FillSetpoint" };
        var settled = new CutShortWrite(intent, intent.Then(AuditStep.ResolvedAtStart, PollingTestClock.Start, "applied", "the PLC holds the requested 16#000003E7"));

        settled.Describe().Should().Be("a write cut short earlier (its program ended before the outcome): station 2 VD100 (FillSetpoint): "
            + "16#00000000 -> 16#000003E7 by root at 2026-11-27T16:38:02.000Z; resolved at start: applied: the PLC holds the requested 16#000003E7");
    }

    private AuditEntry WriteCutShort(string port)
    {
        var intent = WriteJournalTests.Intent(port);
        var ended = WriteJournalTests.EndedProcess();
        Directory.CreateDirectory(_folder);
        File.AppendAllLines(_journal.Path, [new JournalLine(intent, ended.Id, ended.Started).Format()]);
        return intent;
    }
}
