using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Protocol;
using OperatorPanel.ViewModels.Memory;
using OperatorPanel.ViewModels.Tests.Fakes;

namespace OperatorPanel.ViewModels.Tests.Memory;

/// <summary>
/// The Memory window refuses what <c>opanel write</c> refuses, by the same rules and before anything is sent: a REAL the
/// PLC cannot hold, a byte of a tag the project marks read-only, the handler's own V bytes.
/// </summary>
public sealed class MemoryWriteRulesTests : IAsyncDisposable
{
    private readonly PanelFixture _panel = new(Project());
    private readonly MemoryViewModel _memory;

    public MemoryWriteRulesTests() => _memory = new MemoryViewModel(_panel.Session, _panel.Dialogs, _panel.Options, _panel.Logger);

    public async ValueTask DisposeAsync() => await _panel.DisposeAsync();

    [Fact]
    public async Task Commit_RealTooCloseToZero_RefusedNamingTheRealsRangeAndNothingSent()
    {
        await CommitAsync("Temperature", "1.5e-50", expectedError:
            "VD20: 1.5e-50 is too close to 0 for a REAL (a REAL holds 0 and numbers from ±1.175495E-38 to ±3.402823E+38): it would be stored as 0; write 0 or a number inside that range");
    }

    [Fact]
    public async Task Commit_CellInsideAReadOnlyTag_RefusedNamingTheTagAndNothingSent()
    {
        await CommitAsync("LevelLowByte", "5", expectedError: "VB151 is part of tag TankLevel (VW150), which the project marks read-only");
    }

    [Fact]
    public async Task Commit_CellInTheHandlersOwnVBytes_RefusedNamingTheRangeAndNothingSent()
    {
        await CommitAsync("Scratch", "5", expectedError:
            "VB8000 is in the handler's own V bytes VB7586-VB8191 (where generate puts the full handler's buffer, work bytes and list by default; IDENTIFY says where a station's are)");
    }

    [Fact]
    public async Task Commit_RealThatOnlyLosesPrecision_IsWrittenAsTheNearestRealAndConfirmed()
    {
        var cell = await CommitAsync("Temperature", "0.1", expectedError: null);

        _panel.Plc.Memory.ReadDoubleWord(ProtocolArea.V, 20).Should().Be(0x3DCCCCCDu, "0.1 as the nearest single precision number");
        cell.WriteError.Should().BeNull();
        cell.ValueText.Should().Be("0.1");
    }

    private static PanelProject Project()
    {
        var project = PanelFixture.Project();
        var station = project.Stations[0];
        var tags = station.Tags.AddRange(
            new ProjectTag("TankLevel", PlcAddress.Parse("VW150"), DisplayFormat.Signed, Writable: false, string.Empty),
            new ProjectTag("LevelLowByte", PlcAddress.Parse("VB151"), DisplayFormat.Unsigned, Writable: true, string.Empty),
            new ProjectTag("Scratch", PlcAddress.Parse("VB8000"), DisplayFormat.Unsigned, Writable: true, string.Empty));
        return project with { Stations = [station with { Tags = tags }] };
    }

    private async Task<MemoryCellViewModel> CommitAsync(string symbol, string text, string? expectedError)
    {
        await _panel.ConnectAsync();
        await _panel.RefreshAsync();
        var cell = _memory.Cells.Single(c => c.Symbol == symbol);
        var frames = _panel.Transport.FramesSent;
        cell.BeginEditCommand.Execute(null);
        cell.EditText = text;

        await cell.CommitEditCommand.ExecuteAsync(null).Guarded();

        cell.EditError.Should().Be(expectedError);
        if (expectedError is not null)
        {
            _panel.Session.StatusLine.Text.Should().Be(expectedError);
            _panel.Transport.FramesSent.Should().Be(frames, "nothing was sent");
        }

        return cell;
    }
}
