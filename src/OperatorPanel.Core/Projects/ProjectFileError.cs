namespace OperatorPanel.Core.Projects;

/// <summary>One problem found in a project file.</summary>
/// <param name="Location">
/// A JSON path such as <c>$.stations[0].tags[3].address</c> for a wrong value, <c>line 5, column 12</c> for a syntax
/// error, or <c>file</c> when the file itself could not be read.
/// </param>
/// <param name="Message">What is wrong, in a sentence a technician can act on.</param>
public sealed record ProjectFileError(string Location, string Message)
{
    public override string ToString() => $"{Location}: {Message}";
}
