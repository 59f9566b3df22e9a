using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Values;
using OperatorPanel.ViewModels.Memory;
using OperatorPanel.ViewModels.Tests.Fakes;

namespace OperatorPanel.ViewModels.Tests.Memory;

/// <summary>
/// Tags as an HMI has them in the Memory window: a scaled value with its unit (TankLevel 552 is 55.2 %), typed in those
/// units, and a range that refuses a value before anything is sent (RecipeNumber 1..8 refused 99).
/// </summary>
public sealed class MemoryTagUnitsTests : IAsyncDisposable
{
    private readonly PanelFixture _panel = new(Project());
    private readonly MemoryViewModel _memory;

    public MemoryTagUnitsTests() => _memory = new MemoryViewModel(_panel.Session, _panel.Dialogs, _panel.Options, _panel.Logger);

    private MemoryCellViewModel Level => _memory.Cells.Single(c => c.Symbol == "Speed");

    private MemoryCellViewModel Recipe => _memory.Cells.Single(c => c.Symbol == "Recipe");

    public async ValueTask DisposeAsync() => await _panel.DisposeAsync();

    [Fact]
    public async Task Commit_ValueOutsideTheTagsRange_RefusedAndNothingSent()
    {
        await _panel.ConnectAsync();
        await _panel.RefreshAsync();
        var frames = _panel.Transport.FramesSent;
        Recipe.BeginEditCommand.Execute(null);
        Recipe.EditText = "99";

        await Recipe.CommitEditCommand.ExecuteAsync(null).Guarded();

        Recipe.EditError.Should().Be("Recipe (MB4): 99 is outside its range 1..8");
        Recipe.RangeText.Should().Be("1..8");
        _panel.Transport.FramesSent.Should().Be(frames, "nothing was sent");
    }

    [Fact]
    public async Task ScaledCell_ShowsEngineeringValueWithUnitAndWritesTheRawValueOfWhatIsTyped()
    {
        await _panel.ConnectAsync();
        _panel.Plc.Memory.WriteWord(ProtocolArea.V, 10, 552);
        await _panel.RefreshAsync();

        Level.ValueText.Should().Be("55.2 %");
        Level.FormatText.Should().Be("signed, %, 0..1000 -> 0..100");
        Level.BeginEditCommand.Execute(null);
        Level.EditText.Should().Be("55.2", "the operator edits the number in its unit");
        Level.EditText = "60 %";
        await Level.CommitEditCommand.ExecuteAsync(null).Guarded();

        Level.EditError.Should().BeNull();
        _panel.Plc.Memory.ReadWord(ProtocolArea.V, 10).Should().Be(600);
        Level.ValueText.Should().Be("60.0 %");
    }

    private static PanelProject Project()
    {
        var project = PanelFixture.Project();
        var station = project.Stations[0];
        var tags = station.Tags
            .Select(t => t.Symbol switch
            {
                "Speed" => t with { Writable = true, Unit = "%", Scale = new TagScale(0, 1000, 0, 100) },
                "Recipe" => t with { Writable = true, Range = new TagRange(1, 8) },
                _ => t,
            })
            .ToList();
        return project with { Stations = [station with { Tags = [.. tags] }] };
    }
}
