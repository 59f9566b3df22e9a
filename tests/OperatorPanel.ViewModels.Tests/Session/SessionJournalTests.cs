using System.Diagnostics;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Audit;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Writes;
using OperatorPanel.Simulator.Reference;
using OperatorPanel.ViewModels.Session;
using OperatorPanel.ViewModels.Tests.Fakes;

namespace OperatorPanel.ViewModels.Tests.Session;

/// <summary>The panel's writes on record in the write journal, and a write an earlier program left cut short settled on connecting.</summary>
public sealed class SessionJournalTests : IAsyncDisposable
{
    private readonly TempFolder _folder = new();
    private readonly PanelFixture _panel = new();

    public async ValueTask DisposeAsync()
    {
        await _panel.DisposeAsync();
        _folder.Dispose();
    }

    [Fact]
    public async Task Connect_WriteCutShortByAnEarlierProgram_IsReadBackAndShownInTheStatusLine()
    {
        var journal = WriteJournal.In(_folder.Path, _panel.Clock);
        File.WriteAllText(journal.Path, CutShortIntentLine());
        await using var session = Session(journal);

        await session.ConnectAsync(_panel.Connector);

        session.StatusLine.Text.Should().Be("a write cut short earlier (its program ended before the outcome): station 2 VW10 (Speed): 16#0000 -> 16#0005 "
            + "by maria at 2026-11-27T16:38:02.987Z; resolved at start: not applied: the PLC still holds the old 16#0000");
        File.ReadAllText(journal.Path).Should().Contain("\"step\":\"resolvedAtStart\"");
    }

    [Fact]
    public async Task Write_ThroughTheSession_GoesOnRecordWithItsSymbolAndUser()
    {
        var journal = WriteJournal.In(_folder.Path, _panel.Clock);
        await using var session = Session(journal);
        await session.ConnectAsync(_panel.Connector);

        await session.WriteAsync(WriteRequest.Bytes(PanelFixture.Filler, PlcAddress.Parse("VW10"), [0, 7]));

        var lines = File.ReadAllLines(journal.Path);
        lines.Should().HaveCount(2);
        lines[0].Should().Contain("\"step\":\"intent\"").And.Contain("\"symbol\":\"Speed\"").And.Contain($"\"user\":\"{AuditUser.Current}\"").And.Contain("\"port\":\"COM7\"");
        lines[1].Should().Contain("\"step\":\"outcome\"").And.Contain("\"outcome\":\"confirmed\"");
    }

    [Fact]
    public async Task Stop_ThroughTheSession_GoesOnRecordBeforeStopLeavesAndItsOutcomeAfter()
    {
        var journal = WriteJournal.In(_folder.Path, _panel.Clock);
        var project = PanelFixture.Project();
        _panel.Connector.Configure(new HandlerConfig(PanelFixture.Filler, CpuProfiles.For(CpuModel.Cpu224), allowStop: true));
        await using var session = Session(journal, project with { Stations = [project.Stations[0] with { AllowStop = true }] });
        await session.ConnectAsync(_panel.Connector);

        var outcome = await session.StopAsync(PanelFixture.Filler);

        outcome.IsStopped.Should().BeTrue();
        _panel.Plc.Mode.Should().Be(OperatingMode.Stop);
        var lines = File.ReadAllLines(journal.Path);
        lines.Should().HaveCount(2, "the STOP went through the bus's queue, which puts it on record");
        lines[0].Should().Contain("\"step\":\"intent\"").And.Contain("\"action\":\"stop\"").And.Contain("\"old\":\"RUN\"").And.Contain("\"new\":\"STOP\"").And.Contain("\"port\":\"COM7\"");
        lines[1].Should().Contain("\"step\":\"outcome\"").And.Contain("\"outcome\":\"station 2 stopped: the port speaks PPI until someone sets RUN\"");
    }

    private PanelSession Session(WriteJournal journal, PanelProject? project = null) =>
        new(project ?? PanelFixture.Project(), new InlineDispatcher(), _panel.Clock, _panel.Logger, journal)
        {
            LinkOptionsFor = serial => Core.Link.LinkOptions.For(serial) with { InterFrameGap = TimeSpan.Zero },
        };

    /// <summary>An intent of a program that has ended (its process ran and exited), with no outcome after it.</summary>
    private static string CutShortIntentLine()
    {
        using var ended = Process.Start(new ProcessStartInfo("true") { UseShellExecute = false })!;
        ended.WaitForExit();
        return $"{{\"id\":\"{Guid.NewGuid()}\",\"step\":\"intent\",\"action\":\"write\",\"time\":\"2026-11-27T16:38:02.987Z\",\"user\":\"maria\","
            + "\"port\":\"COM7\",\"station\":2,\"target\":\"VW10\",\"symbol\":\"Speed\",\"old\":\"16#0000\",\"new\":\"16#0005\",\"outcome\":null,"
            + $"\"detail\":null,\"pid\":{ended.Id},\"processStarted\":\"2026-11-27T16:38:01.000Z\"}}\n";
    }
}
