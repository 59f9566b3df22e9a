using System.Text.Json.Nodes;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Values;

namespace OperatorPanel.Core.Tests.Projects;

/// <summary>Tags as an HMI has them in the project file: unit, linear scale and range, optional, checked, written back as read.</summary>
public sealed class ProjectFileTagUnitsTests
{
    [Fact]
    public void Load_Sample_ReadsUnitScaleAndRange()
    {
        var tags = ProjectFile.Load(SampleProject.Path).Project!.Stations[0].Tags;

        var level = tags.Single(t => t.Symbol == "TankLevel");
        level.Unit.Should().Be("%");
        level.Scale.Should().Be(new TagScale(0, 1000, 0, 100));
        tags.Single(t => t.Symbol == "RecipeNumber").Range.Should().Be(new TagRange(1, 8));
        tags.Single(t => t.Symbol == "FaultCode").Should().Match<ProjectTag>(t => t.Unit == null && t.Scale == null && t.Range == null);
    }

    [Fact]
    public void Format_TagWithoutUnitScaleOrRange_WritesNoneOfTheirProperties()
    {
        var tree = SampleProject.Tree();
        foreach (var tag in tree.Station()["tags"]!.AsArray())
        {
            foreach (var name in new[] { "unit", "scale", "min", "max" })
            {
                tag!.AsObject().Remove(name);
            }
        }

        var text = ProjectFile.Format(ProjectFile.Parse(tree.ToJsonString()).Project!);

        text.Should().NotContain("\"unit\"").And.NotContain("\"scale\"").And.NotContain("\"min\"").And.NotContain("\"max\"", "a project written before them saves as it was");
    }

    [Theory]
    [InlineData(8, "scale", "{\"rawLow\":0,\"rawHigh\":255,\"low\":0,\"high\":1}", "$.stations[0].tags[8].scale", "scale, min and max are for numbers: the format of VB160 is hex; use unsigned, signed or float")]
    [InlineData(2, "min", "9", "$.stations[0].tags[2].max", "max 8 is below min 9")]
    [InlineData(2, "max", "300", "$.stations[0].tags[2].max", "VB110: 300 is outside 0..255, the range of an unsigned byte (a signed byte takes -128..127)")]
    [InlineData(7, "scale", "{\"rawLow\":0,\"rawHigh\":0,\"low\":0,\"high\":100}", "$.stations[0].tags[7].scale", "rawLow and rawHigh are equal: no raw span to scale")]
    [InlineData(7, "scale", "{\"rawLow\":0,\"rawHigh\":40000,\"low\":0,\"high\":100}", "$.stations[0].tags[7].scale", "rawHigh 40000: VW150: 40000 is outside -32768..32767, the range of a signed word")]
    [InlineData(7, "unit", "\"\"", "$.stations[0].tags[7].unit", "a unit is 1-16 characters without spaces around (\"%\", \"ml\", \"bottles/min\"); leave it out for none")]
    [InlineData(7, "scale", "{\"rawLow\":0,\"rawHigh\":1000,\"low\":0}", "$.stations[0].tags[7].scale", "missing required property 'high'")]
    public void Parse_UnitScaleOrRangeThatDoesNotFit_IsOneProblemAtItsProperty(int tag, string property, string json, string location, string message)
    {
        BadFile.Expect(t => t.Station()["tags"]![tag]![property] = JsonNode.Parse(json), location, message);
    }
}
