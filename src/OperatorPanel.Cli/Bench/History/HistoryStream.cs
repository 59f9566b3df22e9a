using OperatorPanel.Core.Projects;

namespace OperatorPanel.Cli.Bench.History;

/// <summary>A line's values over simulated time, as the bench feeds them: the project they belong to, and a step that publishes what the line would deliver at a time.</summary>
internal interface IHistoryStream
{
    string Name { get; }

    PanelProject Project { get; }

    /// <summary>How often the line delivers a cycle of values.</summary>
    TimeSpan Step { get; }

    /// <summary>Publishes the values of the cycle at <paramref name="elapsed"/> from the start.</summary>
    void Publish(BenchLineValues line, TimeSpan elapsed, DateTimeOffset at);
}
