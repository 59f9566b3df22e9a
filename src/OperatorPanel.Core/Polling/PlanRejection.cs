namespace OperatorPanel.Core.Polling;

/// <summary>A watched item the planner left out, with the reason a technician can act on.</summary>
public sealed record PlanRejection(WatchedItem Item, string Reason);
